// The shock-tube case module: its tube and initial-state keys, checks and scene size.
#include <cmath>
#include <memory>
#include <utility>

#include "sphmol/cases/case_keys.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/cases/shock_tube/shock_tube_case.hpp"
#include "sphmol/cases/shock_tube/shock_tube_settings.hpp"

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

CaseRead read_shock_tube(CaseReaders& r, const Config& c) {
  auto s = std::make_shared<ShockTubeSettings>();
  s->dimension = c.dimension;
  MapReader eos = r.fluid.section("eos", {"type", "sound_speed", "gamma", "background_pressure", "clamp_negative"});
  if (c.fluid.eos.type != "ideal_gas")
    eos.fail("type", "case 'shock_tube' needs type 'ideal_gas' (got '" + c.fluid.eos.type + "')");
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
  for (const char* side : {"left", "right"}) {
    MapReader q = st.section(side, {"density", "pressure", "velocity"});
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
  if (c.dimension == 1 && d.particles_across > 0)
    r.discretization.fail("particles_across", "counts particles across the tube width, which the 1D shock tube does not have; give discretization.spacing");

  const double Lt = s->tube_length, W = s->tube_width;
  const double dx = case_keys::spacing(c, W);
  const double nx = case_keys::whole_spacings(geo, "tube_length", Lt, dx, "geometry.tube_length");
  const double ny = c.dimension == 2 ? case_keys::whole_spacings(geo, "tube_width", W, dx, "geometry.tube_width") : 1.0;
  // One layer more than the support: the gas next to the end walls must stay at rest until t_end.
  const double layers = case_keys::wall_layers(c, 1.0);
  double wall = 2.0 * layers * ny;
  if (c.dimension == 2 && d.boundary == "virtual_repulsive") wall += 2.0 * 2.0 * nx;
  CaseRead out{s, {dx, nx * ny, wall}};
  if (c.dimension == 2 && d.boundary == "wall_particles") out.size.periodic.push_back({geo.where("tube_width"), W});
  return out;
}

// c = sqrt(gamma p / rho): pressures x factor^2 (and velocities x factor) scale every sound speed by
// `factor` at fixed densities. Reported: the sound speed of the left state.
double scale_shock_tube_sound_speed(Config& c, double factor) {
  auto s = std::make_shared<ShockTubeSettings>(c.settings<ShockTubeSettings>());
  for (ShockTubeState* st : {&s->left, &s->right}) {
    st->pressure *= factor * factor;
    st->velocity *= factor;
  }
  const auto& L = s->left;
  c.case_settings = s;
  return L.density > 0.0 ? std::sqrt(c.fluid.eos.gamma * L.pressure / L.density) : 0.0;
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
