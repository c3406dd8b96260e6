// The shock-tube case module: its tube and initial-state keys, checks and scene size.
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sphmol/cases/case_keys.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/cases/shock_tube/shock_tube_case.hpp"
#include "sphmol/cases/shock_tube/shock_tube_settings.hpp"
#include "sphmol/cases/shock_tube/shock_tube_wall_clearance.hpp"
#include "sphmol/kernels/registry.hpp"
#include "sphmol/reference/exact_riemann.hpp"

namespace sphmol {

std::string ShockTubeSettings::to_yaml() const {
  std::string y = "geometry:\n  tube_length: " + number_text(tube_length) + "\n";
  if (dimension > 1) y += "  tube_width: " + number_text(tube_width) + "\n";
  y += "shock_tube:\n";
  for (const auto& [side, q] : {std::pair{"left", left}, std::pair{"right", right}})
    y += std::string("  ") + side + ": {density: " + number_text(q.density) + ", pressure: " + number_text(q.pressure) +
         ", velocity: " + number_text(q.velocity) + "}\n";
  y += "  setup: " + setup + "\n  smoothing: " + number_text(smoothing) + "\n";
  return y;
}

namespace {

// x to 4 significant digits, rounded down (a time allowed must stay allowed as printed).
std::string four_digits_down(double x) {
  if (!(x > 0.0)) return number_text(x);
  const double scale = std::pow(10.0, 3 - static_cast<int>(std::floor(std::log10(x))));
  return number_text(std::floor(x * scale) / scale);
}

// The distance from each end wall within which the gas interacts with the wall particles: the kernel
// support of the end's gas and one spacing more (the wall layers' rule). Measured on the 1D tubes
// against tubes twice as long: when the outermost wave reaches it, the largest density difference is
// 1e-5 of the density, 1e-4 when the shock is one support from the wall (docs/verification.md, "The
// end walls").
std::array<double, 2> end_wall_reach(const Config& c, const ShockTubeSettings& s, double dx) {
  const auto& d = c.discretization;
  const double support = c.dimension == 1 ? kernel_info<1>(d.kernel).support : kernel_info<2>(d.kernel).support;
  const double rho_dense = std::max(s.left.density, s.right.density);
  std::array<double, 2> reach{};
  for (std::size_t k = 0; k < 2; ++k) {
    // The end gas's own spacing (m / rho)^(1/D), and h0 = smoothing_ratio times it (shock_tube_scene.cpp).
    const double rho = k == 0 ? s.left.density : s.right.density;
    const double sp = s.setup == "equal_mass" ? dx * std::pow(rho_dense / rho, 1.0 / c.dimension) : dx;
    reach[k] = (support * d.smoothing_ratio + 1.0) * sp;
  }
  return reach;
}

// "the right-moving shock (1.752 m/s) comes within 0.02 m (...) of the right end wall at t = 0.2284 s"
std::string when_waves_arrive(const ShockTubeClearance& clear, const std::array<double, 2>& reach, double Lt) {
  const std::string wave = std::string(clear.side == 0 ? "left-moving " : "right-moving ") + (clear.shock ? "shock" : "rarefaction head");
  const auto side = static_cast<std::size_t>(clear.side);
  const std::string end = clear.side == 0 ? "left" : "right";
  return clear.t_clear > 0.0
             ? "the " + wave + " (" + four_digits_down(clear.speed) + " m/s) comes within " + four_digits_down(reach[side]) +
                   " m (the kernel support and one spacing) of the " + end + " end wall at t = " + four_digits_down(clear.t_clear) + " s"
             : "the tube's half length " + number_text(0.5 * Lt) + " m lies within the " + end + " end wall's reach, " +
                   four_digits_down(reach[side]) + " m (the kernel support and one spacing), from the start";
}

CaseRead read_shock_tube(CaseReaders& r, const Config& c) {
  auto s = std::make_shared<ShockTubeSettings>();
  s->dimension = c.dimension;
  MapReader eos = r.fluid.section("eos", {"type", "sound_speed", "gamma", "background_pressure", "clamp_negative"});
  if (c.fluid.eos.type != "ideal_gas")
    eos.fail("type", "case 'shock_tube' needs type 'ideal_gas' (got '" + c.fluid.eos.type + "')");
  case_keys::require_no_body_force(r, c, "the exact Riemann solution it is measured against has none");
  MapReader geo = r.top.section("geometry", {"tube_length", "tube_width"});
  s->tube_length = geo.required(geo.real("tube_length"), "tube_length", "fluid extent in x, > 0");
  geo.check("tube_length", s->tube_length > 0, s->tube_length, "> 0");
  if (c.dimension == 1) {
    if (geo.has("tube_width")) geo.fail("tube_width", "is not used in dimension 1");
  } else {
    s->tube_width = geo.required(geo.real("tube_width"), "tube_width", "extent in y, > 0");
    geo.check("tube_width", s->tube_width > 0, s->tube_width, "> 0");
  }
  MapReader st = r.top.section("shock_tube", {"left", "right", "setup", "smoothing"});
  std::vector<MapReader> state_keys;
  for (const char* side : {"left", "right"}) {
    MapReader& q = state_keys.emplace_back(st.section(side, {"density", "pressure", "velocity"}));
    ShockTubeState& state = std::string(side) == "left" ? s->left : s->right;
    state.density = q.required(q.real("density"), "density", "> 0");
    q.check("density", state.density > 0, state.density, "> 0");
    state.pressure = q.required(q.real("pressure"), "pressure", "> 0");
    q.check("pressure", state.pressure > 0, state.pressure, "> 0");
    if (const auto v = q.real("velocity")) state.velocity = *v;
  }
  if (const auto v = st.string("setup")) s->setup = st.choice("setup", *v, {"equal_mass", "equal_spacing"});
  // Default for equal-mass particles across a density jump: a quarter of a spacing in 1D, one spacing
  // in 2D and 3D. The smoothed start spreads the fan before t = 0, so the narrowest jump that runs
  // puts the waves closest to the exact ones (measured on the 1D Sod tube at 2.5e-3, 1.25e-3 and
  // 6.25e-4: rarefaction head -0.70 to -0.85 local spacings with 0.25, -1.4 to -1.6 with 1). In 2D
  // the rows change in number at the jump, and a jump sharper than half a spacing ejects the first
  // particle of the lighter side (measured: negative density at t = 0.005 with 0 and 0.25).
  const bool equal_mass_jump = s->setup == "equal_mass" && s->left.density != s->right.density;
  s->smoothing = equal_mass_jump ? (c.dimension == 1 ? 0.25 : 1.0) : 0.0;
  if (const auto v = st.real("smoothing")) s->smoothing = *v;
  st.check("smoothing", s->smoothing >= 0, s->smoothing, ">= 0 (width in spacings of the denser side; 0 = sharp)");
  const auto& d = c.discretization;
  const bool jump = s->left.density != s->right.density;
  // The lighter side's particles sit (rho_dense / rho_light)^(1/D) spacings apart: a constant h of the
  // denser side would leave them outside each other's support.
  if (s->setup == "equal_mass" && jump && d.smoothing_length == "constant")
    st.fail("setup", "'equal_mass' with a density jump needs a variable smoothing length "
                     "(discretization.smoothing_length: ode or density), or setup: equal_spacing");
  if (s->setup == "equal_mass" && jump && d.boundary == "virtual_repulsive")
    st.fail("setup", "'equal_mass' with a density jump is not available with boundary 'virtual_repulsive' (its wall "
                     "lines are spaced for one lattice); use setup: equal_spacing");
  if (c.dimension == 1 && d.boundary != "wall_particles")
    r.discretization.fail("boundary", "the 1D shock tube has no side walls; '" + d.boundary + "' needs dimension 2");
  // The exact solution (the reference) exists only without a vacuum: Toro (2009) eq 4.40.
  const auto& L = s->left;
  const auto& R = s->right;
  const double gm = c.fluid.eos.gamma, aL = std::sqrt(gm * L.pressure / L.density), aR = std::sqrt(gm * R.pressure / R.density);
  if (2.0 / (gm - 1.0) * (aL + aR) <= R.velocity - L.velocity)
    r.top.fail("shock_tube", "the states separate into a vacuum (right.velocity - left.velocity = " +
                                 number_text(R.velocity - L.velocity) + " >= 2 (aL + aR) / (gamma - 1) = " +
                                 number_text(2.0 / (gm - 1.0) * (aL + aR)) + " m/s), which the exact Riemann solver does not cover");
  // The end walls are at rest: a state moving along the tube pulls away from (or runs into) its end
  // wall from t = 0 and launches a wave there that the infinite tube's solution does not hold.
  for (std::size_t k = 0; k < 2; ++k) {
    const ShockTubeState& q = k == 0 ? L : R;
    if (q.velocity != 0.0)
      state_keys[k].fail("velocity", number_text(q.velocity) + " m/s: the end walls are at rest, so gas moving along the tube "
                         "leaves or runs into its end wall from t = 0 and launches a wave there that the exact (infinite-tube) "
                         "solution does not contain; the shock tube needs both states at rest (velocity 0)");
  }
  if (c.dimension == 1 && d.particles_across > 0)
    r.discretization.fail("particles_across", "counts particles across the tube width, which the 1D shock tube does not have; give discretization.spacing");

  const double Lt = s->tube_length, W = s->tube_width;
  const double dx = case_keys::spacing(c, W);
  // The run is measured against the infinite tube's solution: t_end must come before the outermost
  // waves reach the gas the end walls' particles act on (end_wall_reach).
  {
    const ExactRiemannSolver exact({L.density, 0.0, L.pressure}, {R.density, 0.0, R.pressure}, gm);
    const auto reach = end_wall_reach(c, *s, dx);
    const ShockTubeClearance clear = shock_tube_clearance(exact, 0.5 * Lt, reach);
    if (c.time.t_end > clear.t_clear) {
      const double need = shock_tube_length_for(exact, c.time.t_end, reach);
      const double need_whole = std::ceil(need / dx * (1.0 - 1e-12)) * dx;
      r.time.fail("t_end", number_text(c.time.t_end) + " s is past the time the waves reach the end walls: " + when_waves_arrive(clear, reach, Lt) +
                               "; from then on the run no longer follows the exact solution of an infinite tube it is measured against. " +
                               (clear.t_clear > 0.0 ? "Give time.t_end <= " + four_digits_down(clear.t_clear) + " s, or lengthen" : std::string("Lengthen")) +
                               " the tube: geometry.tube_length >= " + number_text(need_whole) + " m for this t_end");
    }
  }
  const double nx = case_keys::whole_spacings(geo, "tube_length", Lt, dx, "geometry.tube_length");
  const double ny = c.dimension == 2 ? case_keys::whole_spacings(geo, "tube_width", W, dx, "geometry.tube_width") : 1.0;
  // One layer more than the support: the gas next to the end walls must stay at rest until t_end.
  const double layers = case_keys::wall_layers(c, 1.0);
  double wall = 2.0 * layers * ny;
  if (c.dimension == 2 && d.boundary == "virtual_repulsive") wall += 2.0 * 2.0 * nx;
  CaseRead out{s, {dx, nx * ny, wall}};
  if (c.dimension == 2 && d.boundary == "wall_particles") out.size.periodic.push_back({geo.where("tube_width"), W});
  if (c.dimension == 2 && d.boundary == "ghost") out.size.mirror_gaps.push_back({geo.where("tube_width"), W});
  return out;
}

// c = sqrt(gamma p / rho): pressures x factor^2 (and velocities x factor) scale every sound speed by
// `factor` at fixed densities. Reported: the sound speed of the left state.
// Every wave is `factor` times faster, so it reaches the end walls at t_clear / factor: a factor that
// brings that before t_end is refused, since the run would then end in the wall (a gas particle
// pushed out of the tube, "blown up"), which the map would take for an instability of the step.
double scale_shock_tube_sound_speed(Config& c, double factor) {
  auto s = std::make_shared<ShockTubeSettings>(c.settings<ShockTubeSettings>());
  for (ShockTubeState* st : {&s->left, &s->right}) {
    st->pressure *= factor * factor;
    st->velocity *= factor;
  }
  const auto& L = s->left;
  const auto& R = s->right;
  const double gm = c.fluid.eos.gamma;
  const auto reach = end_wall_reach(c, *s, case_keys::spacing(c, s->tube_width));
  const ShockTubeClearance clear = shock_tube_clearance(
      ExactRiemannSolver({L.density, 0.0, L.pressure}, {R.density, 0.0, R.pressure}, gm), 0.5 * s->tube_length, reach);
  if (c.time.t_end > clear.t_clear)
    throw ConfigError("sound speed factor " + number_text(factor) + ": the waves, " + number_text(factor) +
                      " times faster, reach the end walls before time.t_end = " + number_text(c.time.t_end) + " s: " +
                      when_waves_arrive(clear, reach, s->tube_length) +
                      ". The run would end in the wall, not in an instability of the step. Give factors <= " +
                      four_digits_down(factor * clear.t_clear / c.time.t_end) +
                      " for this t_end, a shorter time.t_end or a longer geometry.tube_length");
  c.case_settings = s;
  return L.density > 0.0 ? std::sqrt(gm * L.pressure / L.density) : 0.0;
}

}  // namespace

CaseModule shock_tube_module() {
  CaseModule m;
  m.name = "shock_tube";
  m.description = "Sod-type shock tube of an ideal gas against the exact Riemann solution";
  m.dimensions = {1, 2};
  m.sections = {"geometry", "shock_tube"};
  m.uses_fluid_density = false;
  m.provides_energy = true;
  // The tube's walls are free-slip (Niedoba 2012, §3.2): an inviscid gas.
  m.defaults = [](Config& c) { c.discretization.wall_slip = "free_slip"; };
  m.read = read_shock_tube;
  m.scale_sound_speed = scale_shock_tube_sound_speed;
  m.make1 = [] { return std::make_unique<ShockTubeCase<1>>(); };
  m.make2 = [] { return std::make_unique<ShockTubeCase<2>>(); };
  return m;
}

}  // namespace sphmol
