#pragma once
// Field values at arbitrary points from the fluid particles: the Shepard-normalised SPH interpolant
//   f(x) = sum_j V_j f_j W(|x - x_j|, h) / sum_j V_j W(|x - x_j|, h),   V_j = m_j / rho_j
// (Shepard 1968; in SPH e.g. Monaghan 2005, sec 2), which reproduces a constant exactly and stays
// bounded next to a free surface, where the plain sum sum_j V_j f_j W lacks neighbours. The
// denominator alone is the kernel sum of the fluid, about 1 inside it and 0 outside: the free-surface
// gauges (height_gauge.hpp) look for its 1/2 level. Particles are binned into cells of the kernel
// support once per state, so one sample costs its neighbours only; periodic directions wrap.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "sphmol/core/domain.hpp"
#include "sphmol/geometry/vec.hpp"

namespace sphmol {

template <int D>
class FluidSampler {
 public:
  using Vec = geometry::Vec<D>;
  using KernelW = double (*)(double r, double h);

  // x: D arrays of n positions; volume: n values m/rho; W with support radius support_h * h.
  FluidSampler(const std::array<const double*, D>& x, const double* volume, std::size_t n, KernelW W, double h,
               double support_h, const Domain<D>& domain)
      : x_(x), volume_(volume), n_(n), W_(W), h_(h), radius_(support_h * h), domain_(domain) {
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
      cell[j] = cell_of(point(j));
      ++start_[cell[j] + 1];
    }
    for (std::size_t c = 0; c < total; ++c) start_[c + 1] += start_[c];
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t j = 0; j < n; ++j) order_[fill[cell[j]]++] = static_cast<std::uint32_t>(j);
  }

  // sum_j V_j W: the kernel sum of the fluid at p.
  double kernel_sum(const Vec& p) const {
    double s = 0.0;
    for_each_near(p, [&](std::size_t j, double w) { s += volume_[j] * w; });
    return s;
  }

  // Shepard interpolation of the per-particle values f at p; NaN where no fluid particle is within
  // the kernel support (the point is outside the fluid).
  double interpolate(const Vec& p, const double* f) const {
    double num = 0.0, den = 0.0;
    for_each_near(p, [&](std::size_t j, double w) {
      num += volume_[j] * f[j] * w;
      den += volume_[j] * w;
    });
    return den > 0.0 ? num / den : std::numeric_limits<double>::quiet_NaN();
  }

 private:
  Vec point(std::size_t j) const {
    Vec p;
    for (int d = 0; d < D; ++d) p[d] = x_[d][j];
    return p;
  }
  long axis_cell(int d, double v) const {
    const long c = static_cast<long>(std::floor((domain_.wrap(d, v) - lo_[d]) / width_[d]));
    return std::clamp<long>(c, 0, cells_[d] - 1);
  }
  std::size_t cell_of(const Vec& p) const {
    std::size_t c = 0;
    for (int d = D - 1; d >= 0; --d) c = c * static_cast<std::size_t>(cells_[d]) + static_cast<std::size_t>(axis_cell(d, p[d]));
    return c;
  }

  // Calls f(j, W(|p - x_j|)) for every particle within the support of p (the 3^D cells around p).
  template <class F>
  void for_each_near(const Vec& p, F&& f) const {
    std::array<long, D> base{}, k{};
    for (int d = 0; d < D; ++d) {
      // Outside the particles' box in a bounded direction: the nearest cell row still holds every
      // particle within the radius, since cells are at least the radius wide.
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
          for (int d = 0; d < D; ++d) {
            const double dx = domain_.min_image(d, p[d] - x_[d][j]);
            r2 += dx * dx;
          }
          if (r2 < radius_ * radius_) f(j, W_(std::sqrt(r2), h_));
        }
      int d = 0;
      for (; d < D; ++d) {
        if (++k[d] <= 1) break;
        k[d] = -1;
      }
      if (d == D) break;
    }
  }

  std::array<const double*, D> x_;
  const double* volume_;
  std::size_t n_;
  KernelW W_;
  double h_, radius_;
  Domain<D> domain_;
  Vec lo_{}, width_{};
  std::array<long, D> cells_{};
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> order_;
};

}  // namespace sphmol
