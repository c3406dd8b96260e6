#pragma once
// Field values at arbitrary points from the fluid particles: the Shepard-normalised SPH interpolant
//   f(x) = sum_j V_j f_j W(|x - x_j|, h) / sum_j V_j W(|x - x_j|, h),   V_j = m_j / rho_j
// (Shepard 1968; in SPH e.g. Monaghan 2005, sec 2), which reproduces a constant exactly and stays
// bounded next to a free surface, where the plain sum sum_j V_j f_j W lacks neighbours. The
// denominator alone is the kernel sum of the fluid, about 1 inside it and 0 outside: the free-surface
// gauges (height_gauge.hpp) look for its 1/2 level. Particles are binned into cells of the kernel
// support once per state (point_bins.hpp), so one sample costs its neighbours only; periodic
// directions wrap.
#include <array>
#include <limits>
#include <utility>

#include "sphmol/probes/point_bins.hpp"

namespace sphmol {

template <int D>
class FluidSampler {
 public:
  using Vec = geometry::Vec<D>;
  using KernelW = double (*)(double r, double h);

  // x: D arrays of n positions; volume: n values m/rho; W with support radius support_h * h.
  FluidSampler(const std::array<const double*, D>& x, const double* volume, std::size_t n, KernelW W, double h,
               double support_h, const Domain<D>& domain)
      : bins_(x, n, support_h * h, domain), volume_(volume), W_(W), h_(h) {}
  // Over ranks: a rank's own particles in the cells of the whole fluid's box (PointBins::bounds of
  // every rank's fluid), so that weights() visits the whole sampler's neighbours in its order.
  FluidSampler(const std::array<const double*, D>& x, const double* volume, std::size_t n, KernelW W, double h,
               double support_h, const Domain<D>& domain, const std::pair<Vec, Vec>& box)
      : bins_(x, n, support_h * h, domain, box), volume_(volume), W_(W), h_(h) {}

  // The terms of the sums below: f(cell, j, w) with w = V_j W, in the order the sums add them
  // (PointBins::for_each_near_ordered: by cell, then j).
  template <class F>
  void weights(const Vec& p, F&& f) const {
    bins_.for_each_near_ordered(p, [&](int cell, std::size_t j, double r, const auto&) { f(cell, j, volume_[j] * W_(r, h_)); });
  }

  // sum_j V_j W: the kernel sum of the fluid at p.
  double kernel_sum(const Vec& p) const {
    double s = 0.0;
    bins_.for_each_near(p, [&](std::size_t j, double r, const auto&) { s += volume_[j] * W_(r, h_); });
    return s;
  }

  // Shepard interpolation of the per-particle values f at p; NaN where no fluid particle is within
  // the kernel support (the point is outside the fluid).
  double interpolate(const Vec& p, const double* f) const {
    double num = 0.0, den = 0.0;
    bins_.for_each_near(p, [&](std::size_t j, double r, const auto&) {
      const double w = volume_[j] * W_(r, h_);
      num += f[j] * w;
      den += w;
    });
    return den > 0.0 ? num / den : std::numeric_limits<double>::quiet_NaN();
  }

 private:
  PointBins<D> bins_;
  const double* volume_;
  KernelW W_;
  double h_;
};

}  // namespace sphmol
