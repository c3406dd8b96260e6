#include "sphmol/scenes/box_scene.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "sphmol/geometry/box_shape.hpp"
#include "sphmol/geometry/lattice.hpp"
#include "sphmol/geometry/wall_layers.hpp"
#include "sphmol/kernels/registry.hpp"
#include "sphmol/scenes/lattice_mass.hpp"
#include "sphmol/scenes/position_noise.hpp"

namespace sphmol {

template <int D>
BoxSceneOf<D> build_box_scene(const Config& config, const std::array<double, D>& box, double fluid_height,
                              BoxWalls<D> walls, bool periodic) {
  const auto& disc = config.discretization;
  const double Lx = box[0], Ly = box[D - 1];
  const int nx = disc.particles_across > 0 ? disc.particles_across : static_cast<int>(std::lround(Lx / disc.spacing));
  const double dx = Lx / nx;
  if (nx <= 0 || (disc.particles_across == 0 && std::abs(nx * disc.spacing - Lx) > 1e-6 * Lx))
    throw std::invalid_argument("discretization.spacing: the box width must be a whole number of spacings");
  for (int d = 1; d + 1 < D; ++d)
    if (const long n = std::lround(box[d] / dx); n <= 0 || std::abs(n * dx - box[d]) > 1e-6 * box[d])
      throw std::invalid_argument("geometry.box: lengths must be whole numbers of the spacing " + std::to_string(dx) + " m");
  const int ny = static_cast<int>(std::lround(fluid_height / dx));
  const int ny_box = static_cast<int>(std::lround(Ly / dx));
  if (std::abs(ny * dx - fluid_height) > 1e-6 * Ly || std::abs(ny_box * dx - Ly) > 1e-6 * Ly)
    throw std::invalid_argument("geometry.box: heights must be whole numbers of the spacing " + std::to_string(dx) + " m");
  const double h = disc.smoothing_ratio * dx;
  const double support = kernel_info<D>(disc.kernel).support * h;
  const int layers = disc.wall_layers > 0 ? disc.wall_layers : static_cast<int>(std::ceil(support / dx));
  const double rho0 = config.fluid.density;
  const double m = lattice_mass<D>(disc.particle_mass, disc.kernel, rho0, dx, h);

  BoxSceneOf<D> s;
  s.spacing = dx;
  s.wall_layers = layers;
  for (int d = 0; d < D; ++d) {
    s.cells[d] = static_cast<int>(std::lround((d == D - 1 ? fluid_height : box[d]) / dx));
    walls[d][0].position = 0.0;
    walls[d][1].position = box[d];
    for (int side = 0; side < 2; ++side) walls[d][side].no_slip = disc.wall_slip != "free_slip";
    s.domain.periodic[d] = periodic;
    s.domain.lo[d] = periodic ? 0.0 : -layers * dx;
    s.domain.hi[d] = periodic ? box[d] : box[d] + layers * dx;
    // A face without a wall (the open top of a tank) lets fluid out (run/outflow.hpp).
    for (int side = 0; side < 2; ++side) s.domain.outflow[d][side] = !periodic && !walls[d][side].present;
  }
  s.walls = walls;

  geometry::Lattice<D> lattice;  // cell centres (i + 1/2) dx from the origin
  lattice.spacing = dx;
  geometry::Vec<D> fluid_hi = box;
  fluid_hi[D - 1] = fluid_height;
  for (const auto& x : geometry::fill<D>(geometry::BoxShape<D>({}, fluid_hi), lattice))
    s.particles.add(Kind::Fluid, x, {}, m, rho0);
  add_position_noise(s.particles, disc.position_noise * dx);
  if (periodic) return s;

  if (disc.boundary == "wall_particles") {
    std::array<bool, 2 * D> open{};
    for (int f = 0; f < 2 * D; ++f) open[f] = !walls[f / 2][f % 2].present;
    // The top face (a moving lid) takes the corners.
    for (const auto& w : geometry::box_container_walls<D>({}, box, open, lattice, layers * dx, 2 * D - 1)) {
      const auto& wall = walls[w.face / 2][w.face % 2];
      s.particles.add(Kind::Wall, w.x, wall.velocity, m, rho0, w.normal, w.depth);
      for (int d = 0; d < D; ++d)
        if (wall.velocity[d] != 0.0) s.particles.stationary.back() = 1;
    }
  } else if (disc.boundary == "virtual_repulsive") {
    if constexpr (D != 2) {
      throw std::invalid_argument("discretization.boundary: virtual_repulsive walls are two-dimensional only");
    } else {
      const double ds = 0.5 * dx;
      for (int d = 0; d < 2; ++d)
        for (int side = 0; side < 2; ++side) {
          if (!walls[d][side].present) continue;
          const int o = 1 - d;  // along the wall
          const int steps = static_cast<int>(std::lround(box[o] / ds));
          // corners belong to the x-walls (d == 0) only, so no point is placed twice
          for (int k = (d == 1 ? 1 : 0); k <= (d == 1 ? steps - 1 : steps); ++k) {
            std::array<double, 2> x{};
            x[d] = side == 0 ? 0.0 : box[d];
            x[o] = k * ds;
            s.particles.add(Kind::Wall, x, {0.0, 0.0}, 0.0, rho0);
          }
        }
    }
  }
  return s;
}

template BoxSceneOf<2> build_box_scene<2>(const Config&, const std::array<double, 2>&, double, BoxWalls<2>, bool);
template BoxSceneOf<3> build_box_scene<3>(const Config&, const std::array<double, 3>&, double, BoxWalls<3>, bool);

}  // namespace sphmol
