#include "sphmol/scenes/box_scene.hpp"

#include <cmath>
#include <stdexcept>

#include "sphmol/kernels/registry.hpp"
#include "sphmol/scenes/lattice_mass.hpp"
#include "sphmol/scenes/position_noise.hpp"

namespace sphmol {

BoxScene build_box_scene(const Config& config, double Lx, double Ly, double fluid_height, BoxWalls<2> walls,
                         bool periodic) {
  const auto& disc = config.discretization;
  const int nx = disc.particles_across > 0 ? disc.particles_across : static_cast<int>(std::lround(Lx / disc.spacing));
  const double dx = Lx / nx;
  if (nx <= 0 || (disc.particles_across == 0 && std::abs(nx * disc.spacing - Lx) > 1e-6 * Lx))
    throw std::invalid_argument("discretization.spacing: the box width must be a whole number of spacings");
  const int ny = static_cast<int>(std::lround(fluid_height / dx));
  const int ny_box = static_cast<int>(std::lround(Ly / dx));
  if (std::abs(ny * dx - fluid_height) > 1e-6 * Ly || std::abs(ny_box * dx - Ly) > 1e-6 * Ly)
    throw std::invalid_argument("geometry.box: heights must be whole numbers of the spacing " + std::to_string(dx) + " m");
  const double h = disc.smoothing_ratio * dx;
  const double support = kernel_info<2>(disc.kernel).support * h;
  const int layers = disc.wall_layers > 0 ? disc.wall_layers : static_cast<int>(std::ceil(support / dx));
  const double rho0 = config.fluid.density;
  const double m = lattice_particle_mass<2>(disc.kernel, rho0, dx, h);

  BoxScene s;
  s.spacing = dx;
  s.nx = nx;
  s.ny = ny;
  s.wall_layers = layers;
  walls[0][0].position = 0.0;
  walls[0][1].position = Lx;
  walls[1][0].position = 0.0;
  walls[1][1].position = Ly;
  for (int d = 0; d < 2; ++d)
    for (int side = 0; side < 2; ++side) walls[d][side].no_slip = disc.wall_slip != "free_slip";
  s.walls = walls;
  s.domain.periodic = {periodic, periodic};
  s.domain.lo = {periodic ? 0.0 : -layers * dx, periodic ? 0.0 : -layers * dx};
  s.domain.hi = {periodic ? Lx : Lx + layers * dx, periodic ? Ly : Ly + layers * dx};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) s.particles.add(Kind::Fluid, {(i + 0.5) * dx, (j + 0.5) * dx}, {0.0, 0.0}, m, rho0);
  add_position_noise(s.particles, disc.position_noise * dx);
  if (periodic) return s;

  const std::array<double, 2> L{Lx, Ly};
  if (disc.boundary == "wall_particles") {
    const int jtop = walls[1][1].present ? ny_box + layers : ny_box;
    for (int j = -layers; j < jtop; ++j)
      for (int i = -layers; i < nx + layers; ++i) {
        const std::array<double, 2> x{(i + 0.5) * dx, (j + 0.5) * dx};
        // depth behind each face (<= 0: inside)
        double depth[2][2];
        bool outside = false, allowed = true;
        for (int d = 0; d < 2; ++d) {
          depth[d][0] = -x[d];
          depth[d][1] = x[d] - L[d];
          for (int side = 0; side < 2; ++side)
            if (depth[d][side] > 0) {
              outside = true;
              allowed = allowed && walls[d][side].present;
            }
        }
        if (!outside || !allowed) continue;
        int bd = -1, bs = 0;
        if (depth[1][1] > 0) {
          bd = 1;
          bs = 1;
        } else {
          double best = 0.0;
          for (int d = 0; d < 2; ++d)
            for (int side = 0; side < 2; ++side)
              if (depth[d][side] >= best && depth[d][side] > 0) {
                best = depth[d][side];
                bd = d;
                bs = side;
              }
        }
        const auto& w = walls[bd][bs];
        std::array<double, 2> normal{};
        normal[bd] = bs == 0 ? 1.0 : -1.0;
        s.particles.add(Kind::Wall, x, w.velocity, m, rho0, normal, depth[bd][bs]);
        if (w.velocity[0] != 0.0 || w.velocity[1] != 0.0) s.particles.stationary.back() = 1;
      }
  } else if (disc.boundary == "virtual_repulsive") {
    const double ds = 0.5 * dx;
    for (int d = 0; d < 2; ++d)
      for (int side = 0; side < 2; ++side) {
        if (!walls[d][side].present) continue;
        const int o = 1 - d;  // along the wall
        const int steps = static_cast<int>(std::lround(L[o] / ds));
        // corners belong to the x-walls (d == 0) only, so no point is placed twice
        for (int k = (d == 1 ? 1 : 0); k <= (d == 1 ? steps - 1 : steps); ++k) {
          std::array<double, 2> x{};
          x[d] = side == 0 ? 0.0 : L[d];
          x[o] = k * ds;
          s.particles.add(Kind::Wall, x, {0.0, 0.0}, 0.0, rho0);
        }
      }
  }
  return s;
}

}  // namespace sphmol
