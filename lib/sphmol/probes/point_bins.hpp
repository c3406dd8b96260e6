#pragma once
// Points binned into cells at least `radius` wide, so that the points within `radius` of any
// position are found in the 3^D cells around it; periodic directions wrap (minimum image). Built
// once per state by the probes (fluid_sampler.hpp, wall_force.hpp): one query costs its neighbours.
// A query visits the cells in a fixed order and each cell's points in ascending index, so a sum
// over the neighbours has a definite order; over ranks each rank bins its own points in the cells
// of the whole set (the box of all ranks' points) and reports each neighbour's visit number
// (for_each_near_ordered), so that the root can add the ranks' terms in that same order.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "sphmol/core/domain.hpp"
#include "sphmol/geometry/vec.hpp"

namespace sphmol {

template <int D>
class PointBins {
 public:
  using Vec = geometry::Vec<D>;

  // The smallest and largest coordinate of n points per axis (+inf, -inf without points): min and
  // max are exact, so the box of several sets is that of their union.
  static std::pair<Vec, Vec> bounds(const std::array<const double*, D>& x, std::size_t n) {
    Vec lo, hi;
    for (int d = 0; d < D; ++d) {
      lo[d] = std::numeric_limits<double>::infinity();
      hi[d] = -lo[d];
      for (std::size_t j = 0; j < n; ++j) {
        lo[d] = std::min(lo[d], x[d][j]);
        hi[d] = std::max(hi[d], x[d][j]);
      }
    }
    return {lo, hi};
  }

  // x: D arrays of n positions (kept by pointer: they must outlive the bins).
  PointBins(const std::array<const double*, D>& x, std::size_t n, double radius, const Domain<D>& domain)
      : PointBins(x, n, radius, domain, bounds(x, n)) {}
  // The same with the cells of the box `box` (bounds() of a set that includes these points: the
  // whole set's, over ranks), so that a query visits the cells of the whole set's bins.
  PointBins(const std::array<const double*, D>& x, std::size_t n, double radius, const Domain<D>& domain,
            const std::pair<Vec, Vec>& box)
      : x_(x), radius_(radius), domain_(domain) {
    for (int d = 0; d < D; ++d) {
      lo_[d] = box.first[d];
      double hi = box.second[d];
      if (!(lo_[d] <= hi)) lo_[d] = hi = 0.0;  // no points at all
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
    for_each_near_ordered(p, [&](int, std::size_t j, double r, const std::array<double, D>& dx) { f(j, r, dx); });
  }

  // The same, in the same order, calling f(cell, j, r, dx) with the number of j's cell in the
  // query's visit (0 to 3^D - 1): the visit is ordered by (cell, j).
  template <class F>
  void for_each_near_ordered(const Vec& p, F&& f) const {
    int visit = 0;
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
          if (r2 < radius_ * radius_) f(visit, j, std::sqrt(r2), dx);
        }
      ++visit;
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
