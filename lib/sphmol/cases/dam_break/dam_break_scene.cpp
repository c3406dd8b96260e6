#include "sphmol/cases/dam_break/dam_break_scene.hpp"
#include "sphmol/cases/dam_break/dam_break_settings.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

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
  const int nx_tank = whole_spacings(Lx, dx, "geometry.box[0]"), ny_tank = whole_spacings(Ly, dx, "geometry.box[1]");
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
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double y = (j + 0.5) * dx;
      s.particles.add(Kind::Fluid, {(i + 0.5) * dx, y}, {0.0, 0.0}, m, hydrostatic(y));
    }
  // Walls: bottom rows (corners included) then the two side walls up to the tank height.
  for (int j = -layers; j < ny_tank; ++j)
    for (int i = -layers; i < nx_tank + layers; ++i) {
      const bool bottom = j < 0, left = i < 0, right = i >= nx_tank;
      if (!bottom && !left && !right) continue;
      const std::array<double, 2> x{(i + 0.5) * dx, (j + 0.5) * dx};
      std::array<double, 2> normal{0.0, 1.0};
      double depth = -x[1];
      if (!bottom) {
        normal = {left ? 1.0 : -1.0, 0.0};
        depth = left ? -x[0] : x[0] - Lx;
      }
      const double rho = x[0] < a ? hydrostatic(x[1]) : rho0;
      s.particles.add(Kind::Wall, x, {0.0, 0.0}, m, rho, normal, depth);
    }
  // Room above the tank for splashes; fluid leaving the domain is a blow-up (run/health_check.hpp).
  const double margin = layers * dx + 2.0 * support;
  s.domain.periodic = {false, false};
  s.domain.lo = {-margin, -margin};
  s.domain.hi = {Lx + margin, std::max(Ly, 2.0 * H) + margin};
  return s;
}

}  // namespace sphmol
