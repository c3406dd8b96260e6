#pragma once
// Free-surface height along a vertical line: the highest point where the kernel sum of the fluid
// (FluidSampler::kernel_sum, ~1 inside the fluid, 0 outside) is at least 1/2, the level a free
// surface sits at for a symmetric kernel, found by scanning the line upwards in steps of `step` and
// interpolating the crossing linearly (the gauges of DualSPHysics work the same way; Crespo et al.
// 2015). The vertical is the last axis: y in 2D, z in 3D.
#include <cmath>
#include <limits>

#include "sphmol/probes/fluid_sampler.hpp"

namespace sphmol {

// `at`: the line's position (its vertical coordinate is ignored); [bottom, top]: the scanned range.
// NaN when the kernel sum is below 1/2 everywhere on the line (no fluid there).
template <int D>
double free_surface_height(const FluidSampler<D>& fluid, geometry::Vec<D> at, double bottom, double top, double step) {
  constexpr int up = D - 1;
  constexpr double level = 0.5;
  double found = std::numeric_limits<double>::quiet_NaN();
  at[up] = bottom;
  double prev = fluid.kernel_sum(at), z_prev = bottom;
  for (double z = bottom + step; z <= top + 1e-12 * step; z += step) {
    at[up] = z;
    const double s = fluid.kernel_sum(at);
    if (prev >= level && s < level) found = z_prev + (prev - level) / (prev - s) * (z - z_prev);
    prev = s;
    z_prev = z;
  }
  if (prev >= level) found = z_prev;  // still in the fluid at the top of the line
  return found;
}

}  // namespace sphmol
