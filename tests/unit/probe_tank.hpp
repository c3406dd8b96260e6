#pragma once
// A 2D tank of water at hydrostatic density for the probe tests: fluid [0, W] x [0, H], walls
// kLayers deep: the floor is wall body 0, the left wall body 1, the right wall body 2, the corners
// below the left and right walls bodies 3 and 4.
#include <array>

#include "sphmol/config/config.hpp"
#include "sphmol/core/particles.hpp"

namespace probe_tank {

using namespace sphmol;

constexpr double kRho0 = 1000.0, kG = 9.81, kC = 60.0;
constexpr int kNx = 40, kNy = 24, kLayers = 4;
constexpr double kDx = 0.025, kW = kNx * kDx, kH = kNy * kDx;

inline Config tank_config() {
  Config c;
  c.dimension = 2;
  c.fluid.density = kRho0;
  c.fluid.kinematic_viscosity = 1e-3;
  c.fluid.eos.type = "linear_relative";  // p = c^2 (rho - rho0): the hydrostatic state is rho0 + p / c^2
  c.fluid.eos.sound_speed = kC;
  c.fluid.body_force = {0.0, -kG};
  auto& d = c.discretization;
  d.spacing = kDx;
  d.kernel = "wendland_c2";
  d.smoothing_ratio = 2.0;  // support 2 h = 4 dx: the kLayers wall layers fill it
  d.density = "continuity";
  d.viscosity = "morris";
  d.boundary = "wall_particles";
  d.wall_pressure = "extrapolated";  // Adami et al. 2012: wall pressures from the fluid with gravity
  d.wall_model = "prescribed";
  return c;
}

// Fluid [0, W] x [0, H] at hydrostatic density; walls kLayers deep: floor (and corners) body 0,
// left wall body 1, right wall body 2, rising 4 spacings above the surface.
inline Particles<2> tank() {
  Particles<2> P;
  for (int j = 0; j < kNy; ++j)
    for (int i = 0; i < kNx; ++i) {
      const double x = (i + 0.5) * kDx, y = (j + 0.5) * kDx;
      const double rho = kRho0 + kRho0 * kG * (kH - y) / (kC * kC);
      P.add(Kind::Fluid, {x, y}, {0, 0}, rho * kDx * kDx, rho);
    }
  const auto wall = [&](double x, double y, std::array<double, 2> n, double depth, int body) {
    P.add(Kind::Wall, {x, y}, {0, 0}, kRho0 * kDx * kDx, kRho0, n, depth);
    P.body.back() = body;
  };
  for (int k = 1; k <= kLayers; ++k)
    for (int i = -kLayers; i < kNx + kLayers; ++i)
      wall((i + 0.5) * kDx, -(k - 0.5) * kDx, {0, 1}, (k - 0.5) * kDx, i < 0 ? 3 : i >= kNx ? 4 : 0);
  for (int k = 1; k <= kLayers; ++k)
    for (int j = 0; j < kNy + 4; ++j) {
      wall(-(k - 0.5) * kDx, (j + 0.5) * kDx, {1, 0}, (k - 0.5) * kDx, 1);
      wall(kW + (k - 0.5) * kDx, (j + 0.5) * kDx, {-1, 0}, (k - 0.5) * kDx, 2);
    }
  return P;
}

}  // namespace probe_tank
