#pragma once
// Free-surface height along a vertical line: the highest point where the kernel sum of the fluid
// (FluidSampler::kernel_sum, ~1 inside the fluid, 0 outside; beside walls over the part of the
// support they leave open, open_support_sum below) is at least 1/2, the level a free
// surface sits at for a symmetric kernel, found by scanning the line upwards in steps of `step` and
// interpolating the crossing linearly (the gauges of DualSPHysics work the same way; Crespo et al.
// 2015). The vertical is the last axis: y in 2D, z in 3D.
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "sphmol/core/particles.hpp"
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

// The fluid's kernel sum over the part of the support that walls leave open: sum / (1 - walls), with
// `walls` the kernel sum of the wall particles (their volumes m / rho). Beside a wall the fluid fills
// only the open part of the support, so the plain sum falls short of 1 in the water (about 1/2 on
// the wall's face) and the gauge read low or empty there; in open water it is the plain sum. Where
// walls fill more than 3/4 of the support (a point inside a wall) there is no fluid to read: 0.
inline double open_support_sum(double fluid, double walls) {
  const double open = 1.0 - walls;
  return open > 0.25 ? fluid / open : 0.0;
}

// The wall particles where they are at t (moving bodies follow their motions), with their volumes
// m / rho: their kernel sum at any point is a FluidSampler's over these (walls.kernel_sum), built once
// per sample time for every gauge.
template <int D>
struct WallKernelSum {
  std::array<std::vector<double>, D> x;
  std::vector<double> volume;
  std::optional<FluidSampler<D>> walls;
  WallKernelSum(const Particles<D>& P, double t, double (*W)(double, double), double h, double support, const Domain<D>& domain) {
    const auto frames = P.motion_frames(t);
    for (std::size_t j = 0; j < P.size(); ++j) {
      const auto s = P.wall_state(j, frames, t);
      for (int d = 0; d < D; ++d) x[d].push_back(s.x[d]);
      volume.push_back(P.mass[j] / P.rho[j]);
    }
    std::array<const double*, D> xp{};
    for (int d = 0; d < D; ++d) xp[d] = x[d].data();
    walls.emplace(xp, volume.data(), volume.size(), W, h, support, domain);
  }
  WallKernelSum(const WallKernelSum&) = delete;  // the sampler points into x and volume
  WallKernelSum& operator=(const WallKernelSum&) = delete;
  double operator()(const geometry::Vec<D>& p) const { return walls->kernel_sum(p); }
};

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
