#include "sphmol/cases/channel/channel_scene.hpp"
#include "sphmol/cases/channel/channel_settings.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "sphmol/geometry/box_shape.hpp"
#include "sphmol/geometry/lattice.hpp"
#include "sphmol/geometry/wall_layers.hpp"
#include "sphmol/kernels/registry.hpp"
#include "sphmol/scenes/lattice_mass.hpp"

namespace sphmol {

ChannelScene build_channel_scene(const Config& config) {
  const auto& g = config.settings<ChannelSettings>();
  const auto& disc = config.discretization;
  const double l = g.channel_height, L = g.channel_length;
  const int ny = disc.particles_across > 0 ? disc.particles_across : static_cast<int>(std::lround(l / disc.spacing));
  if (ny <= 0 || std::abs(ny * (l / ny) - l) > 1e-9 * l ||
      (disc.particles_across == 0 && std::abs(ny * disc.spacing - l) > 1e-6 * l))
    throw std::invalid_argument("discretization.spacing: channel_height must be a whole number of spacings");
  const double dx = l / ny;
  const int nx = static_cast<int>(std::lround(L / dx));
  if (nx <= 0 || std::abs(nx * dx - L) > 1e-6 * L)
    throw std::invalid_argument("geometry.channel_length: must be a whole number of particle spacings (" +
                                std::to_string(dx) + " m)");
  const double h = disc.smoothing_ratio * dx;
  const double support = kernel_info<2>(disc.kernel).support * h;
  const int layers = disc.wall_layers > 0 ? disc.wall_layers : static_cast<int>(std::ceil(support / dx));

  ChannelScene s;
  s.spacing = dx;
  s.wall_layers = layers;
  s.domain.lo = {0.0, -layers * dx};
  s.domain.hi = {nx * dx, l + layers * dx};
  s.domain.periodic = {true, false};
  const double rho0 = config.fluid.density;
  const double m = lattice_mass<2>(disc.particle_mass, disc.kernel, rho0, dx, h);
  geometry::Lattice<2> lattice;  // cell centres (i + 1/2) dx from the origin
  lattice.spacing = dx;
  for (const auto& x : geometry::fill<2>(geometry::BoxShape<2>({0.0, 0.0}, {nx * dx, l}), lattice))
    s.particles.add(Kind::Fluid, x, {0.0, 0.0}, m, rho0);
  // Walls below y = 0 and above y = l (the x faces are the periodic ends, open). Each wall's layers
  // continue the lattice from its own surface, so a wall particle sits exactly (k + 1/2) dx beyond
  // it; they are listed layer by layer, nearest first, the two walls alternately along x (a fixed
  // order: the adaptive runs' errors depend on the summation order in their last digits).
  std::vector<geometry::WallPoint<2>> walls;
  for (int side = 0; side < 2; ++side) {
    geometry::Lattice<2> from_wall = lattice;
    from_wall.origin[1] = side == 0 ? 0.0 : l;
    const auto w = geometry::box_container_walls<2>({0.0, 0.0}, {nx * dx, l}, {true, true, side == 1, side == 0},
                                                    from_wall, layers * dx);
    walls.insert(walls.end(), w.begin(), w.end());
  }
  const auto order = [dx](const geometry::WallPoint<2>& w) {
    return std::make_tuple(std::lround(w.depth / dx - 0.5), std::lround(w.x[0] / dx - 0.5), w.face);
  };
  std::stable_sort(walls.begin(), walls.end(), [&](const auto& a, const auto& b) { return order(a) < order(b); });
  for (const auto& w : walls) {
    const bool top = w.face == 3;
    s.particles.add(Kind::Wall, w.x, {top ? g.wall_velocity : 0.0, 0.0}, m, rho0, w.normal, w.depth);
  }
  return s;
}

}  // namespace sphmol
