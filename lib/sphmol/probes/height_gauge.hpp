#pragma once
// Free-surface height along a vertical line: the highest point where the kernel sum of the fluid
// (FluidSampler::kernel_sum, ~1 inside the fluid, 0 outside) is at least 1/2, the level a free
// surface sits at for a symmetric kernel, found by scanning the line upwards in steps of `step` and
// interpolating the crossing linearly (the gauges of DualSPHysics work the same way; Crespo et al.
// 2015). The vertical is the last axis: y in 2D, z in 3D.
#include <cmath>
#include <limits>
#include <vector>

#include "sphmol/probes/fluid_sampler.hpp"

namespace sphmol {

// The heights the gauge samples: bottom, bottom + step, ... up to top.
inline std::vector<double> gauge_levels(double bottom, double top, double step) {
  std::vector<double> z{bottom};
  for (double zz = bottom + step; zz <= top + 1e-12 * step; zz += step) z.push_back(zz);
  return z;
}

// The surface from the kernel sums `sum` at the heights `z` (gauge_levels): NaN when the kernel sum
// is below 1/2 everywhere on the line (no fluid there).
inline double surface_height(const std::vector<double>& z, const std::vector<double>& sum) {
  constexpr double level = 0.5;
  double found = std::numeric_limits<double>::quiet_NaN();
  double prev = sum[0], z_prev = z[0];
  for (std::size_t k = 1; k < z.size(); ++k) {
    const double s = sum[k];
    if (prev >= level && s < level) found = z_prev + (prev - level) / (prev - s) * (z[k] - z_prev);
    prev = s;
    z_prev = z[k];
  }
  if (prev >= level) found = z_prev;  // still in the fluid at the top of the line
  return found;
}

// `at`: the line's position (its vertical coordinate is ignored); [bottom, top]: the scanned range.
template <int D>
double free_surface_height(const FluidSampler<D>& fluid, geometry::Vec<D> at, double bottom, double top, double step) {
  const std::vector<double> z = gauge_levels(bottom, top, step);
  std::vector<double> sum(z.size());
  for (std::size_t k = 0; k < z.size(); ++k) {
    at[D - 1] = z[k];
    sum[k] = fluid.kernel_sum(at);
  }
  return surface_height(z, sum);
}

}  // namespace sphmol
