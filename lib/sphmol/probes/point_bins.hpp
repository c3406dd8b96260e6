#pragma once
// Points binned into cells at least `radius` wide, so that the points within `radius` of any
// position are found in the 3^D cells around it; periodic directions wrap (minimum image). Built
// once per state by the probes (fluid_sampler.hpp, wall_force.hpp): one query costs its neighbours.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "sphmol/core/domain.hpp"
#include "sphmol/geometry/vec.hpp"

namespace sphmol {

template <int D>
class PointBins {
 public:
  using Vec = geometry::Vec<D>;

  // x: D arrays of n positions (kept by pointer: they must outlive the bins).
  PointBins(const std::array<const double*, D>& x, std::size_t n, double radius, const Domain<D>& domain)
      : x_(x), radius_(radius), domain_(domain) {
    for (int d = 0; d < D; ++d) {
      lo_[d] = std::numeric_limits<double>::infinity();
      double hi = -lo_[d];
      for (std::size_t j = 0; j < n; ++j) {
        lo_[d] = std::min(lo_[d], x[d][j]);
        hi = std::max(hi, x[d][j]);
      }
      if (n == 0) lo_[d] = hi = 0.0;
      if (domain.periodic[d]) {
        lo_[d] = domain.lo[d];
        hi = domain.hi[d];
      }
      cells_[d] = std::max<long>(1, static_cast<long>(std::floor((hi - lo_[d]) / radius_)) + 1);
      // A periodic axis needs whole cells that tile its period, at least the radius wide.
      if (domain.periodic[d]) cells_[d] = std::max<long>(1, static_cast<long>(std::floor(domain.length(d) / radius_)));
      width_[d] = domain.periodic[d] ? domain.length(d) / static_cast<double>(cells_[d]) : radius_;
    }
    std::size_t total = 1;
    for (int d = 0; d < D; ++d) total *= static_cast<std::size_t>(cells_[d]);
    start_.assign(total + 1, 0);
    order_.resize(n);
    std::vector<std::size_t> cell(n);
    for (std::size_t j = 0; j < n; ++j) {
      cell[j] = cell_of(j);
      ++start_[cell[j] + 1];
    }
    for (std::size_t c = 0; c < total; ++c) start_[c + 1] += start_[c];
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t j = 0; j < n; ++j) order_[fill[cell[j]]++] = static_cast<std::uint32_t>(j);
  }

  double radius() const { return radius_; }

  // Calls f(j, r, dx) for every point j with r = |p - x_j| < radius, dx = p - x_j (minimum image).
  template <class F>
  void for_each_near(const Vec& p, F&& f) const {
    std::array<long, D> base{}, k{};
    for (int d = 0; d < D; ++d) {
      // Outside the points' box in a bounded direction: the nearest cell row still holds every
      // point within the radius, since cells are at least the radius wide.
      const double rel = (domain_.wrap(d, p[d]) - lo_[d]) / width_[d];
      base[d] = static_cast<long>(std::floor(rel));
      k[d] = -1;
    }
    while (true) {
      std::size_t c = 0;
      bool valid = true;
      for (int d = D - 1; d >= 0 && valid; --d) {
        long cd = base[d] + k[d];
        if (domain_.periodic[d]) cd = ((cd % cells_[d]) + cells_[d]) % cells_[d];
        else if (cd < 0 || cd >= cells_[d]) valid = false;
        c = c * static_cast<std::size_t>(cells_[d]) + static_cast<std::size_t>(std::max<long>(cd, 0));
      }
      // With fewer than 3 cells on a periodic axis the same cell comes up twice: visit it once.
      for (int d = 0; d < D && valid; ++d)
        if (domain_.periodic[d] && cells_[d] < 3 && k[d] >= cells_[d] - 1 && k[d] > -1) valid = false;
      if (valid)
        for (std::size_t s = start_[c]; s < start_[c + 1]; ++s) {
          const std::size_t j = order_[s];
          double r2 = 0.0;
          std::array<double, D> dx{};
          for (int d = 0; d < D; ++d) {
            dx[d] = domain_.min_image(d, p[d] - x_[d][j]);
            r2 += dx[d] * dx[d];
          }
          if (r2 < radius_ * radius_) f(j, std::sqrt(r2), dx);
        }
      int d = 0;
      for (; d < D; ++d) {
        if (++k[d] <= 1) break;
        k[d] = -1;
      }
      if (d == D) break;
    }
  }

 private:
  long axis_cell(int d, double v) const {
    const long c = static_cast<long>(std::floor((domain_.wrap(d, v) - lo_[d]) / width_[d]));
    return std::clamp<long>(c, 0, cells_[d] - 1);
  }
  std::size_t cell_of(std::size_t j) const {
    std::size_t c = 0;
    for (int d = D - 1; d >= 0; --d) c = c * static_cast<std::size_t>(cells_[d]) + static_cast<std::size_t>(axis_cell(d, x_[d][j]));
    return c;
  }

  std::array<const double*, D> x_;
  double radius_;
  Domain<D> domain_;
  Vec lo_{}, width_{};
  std::array<long, D> cells_{};
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> order_;
};

}  // namespace sphmol
