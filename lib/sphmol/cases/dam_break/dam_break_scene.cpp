#include "sphmol/cases/dam_break/dam_break_scene.hpp"
#include "sphmol/cases/dam_break/dam_break_settings.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "sphmol/geometry/box_shape.hpp"
#include "sphmol/geometry/lattice.hpp"
#include "sphmol/geometry/wall_layers.hpp"
#include "sphmol/kernels/registry.hpp"
#include "sphmol/physics/eos_tait.hpp"

namespace sphmol {

namespace {
int whole_spacings(double length, double dx, const std::string& what) {
  const int n = static_cast<int>(std::lround(length / dx));
  if (n <= 0 || std::abs(n * dx - length) > 1e-6 * length)
    throw std::invalid_argument(what + " (" + std::to_string(length) + " m) must be a whole number of the spacing " +
                                std::to_string(dx) + " m");
  return n;
}
}  // namespace

DamBreakScene build_dam_break_scene(const Config& config) {
  const auto& disc = config.discretization;
  const double Lx = config.settings<DamBreakSettings>().box[0], Ly = config.settings<DamBreakSettings>().box[1];
  const double a = config.settings<DamBreakSettings>().column[0], H = config.settings<DamBreakSettings>().column[1];
  // particles_across counts particles across the column width a.
  const double dx = disc.particles_across > 0 ? a / disc.particles_across : disc.spacing;
  const int nx = whole_spacings(a, dx, "geometry.column[0]"), ny = whole_spacings(H, dx, "geometry.column[1]");
  // The tank must be a whole number of spacings too (checked; the counts themselves are not needed).
  whole_spacings(Lx, dx, "geometry.box[0]");
  whole_spacings(Ly, dx, "geometry.box[1]");
  if (config.fluid.body_force.size() != 2 || config.fluid.body_force[0] != 0.0 || !(config.fluid.body_force[1] < 0.0))
    throw std::invalid_argument("fluid.body_force: dam_break needs gravity [0, -g] with g > 0");
  const double g = -config.fluid.body_force[1];
  const double rho0 = config.fluid.density, c = config.fluid.eos.sound_speed;

  std::function<double(double)> rho_of_p;
  if (config.fluid.eos.type == "tait") {
    const TaitLaw law(c, rho0, config.fluid.eos.gamma);
    rho_of_p = [law](double p) { return law.density(p); };
  } else if (config.fluid.eos.type == "linear_relative") {
    rho_of_p = [rho0, c](double p) { return rho0 + p / (c * c); };
  } else {
    throw std::invalid_argument("fluid.eos.type: dam_break needs 'tait' or 'linear_relative' (got '" +
                                config.fluid.eos.type + "')");
  }
  const double h = disc.smoothing_ratio * dx;
  const double support = kernel_info<2>(disc.kernel).support * h;
  const int layers = disc.wall_layers > 0 ? disc.wall_layers : static_cast<int>(std::ceil(support / dx));
  const double m = rho0 * dx * dx;
  const auto hydrostatic = [&](double y) { return rho_of_p(rho0 * g * std::max(0.0, H - y)); };

  DamBreakScene s;
  s.spacing = dx;
  s.wall_layers = layers;
  s.g = g;
  geometry::Lattice<2> lattice;  // cell centres (i + 1/2) dx from the origin
  lattice.spacing = dx;
  for (const auto& x : geometry::fill<2>(geometry::BoxShape<2>({0.0, 0.0}, {nx * dx, ny * dx}), lattice))
    s.particles.add(Kind::Fluid, x, {0.0, 0.0}, m, hydrostatic(x[1]));
  // Walls: the floor (it takes the corners) and the two side walls up to the tank height; open top.
  for (const auto& w : geometry::box_container_walls<2>({0.0, 0.0}, {Lx, Ly}, {false, false, false, true}, lattice,
                                                        layers * dx, 2)) {
    const double rho = w.x[0] < a ? hydrostatic(w.x[1]) : rho0;
    s.particles.add(Kind::Wall, w.x, {0.0, 0.0}, m, rho, w.normal, w.depth);
  }
  // Room above the tank for splashes: a jet at the Ritter front speed 2 sqrt(gH) rises v^2 / 2g = 2H.
  // Fluid that leaves anyway (a run-up jet the impact drives faster, a splash over the side walls) is
  // taken out of the run (run/outflow.hpp): through the top, and through the sides, whose faces are
  // not the walls (those are the wall particles inside the box; a particle through them is a wall
  // penetration, which the case counts). Below the floor's layers there is no way out.
  const double margin = layers * dx + 2.0 * support;
  s.domain.periodic = {false, false};
  s.domain.outflow = {{{true, true}, {false, true}}};
  s.domain.lo = {-margin, -margin};
  s.domain.hi = {Lx + margin, std::max(Ly, 2.0 * H) + margin};
  return s;
}

}  // namespace sphmol
