// Config keys of the box cases, Tait EOS and boundaries: accepted combinations round-trip through
// to_yaml, nonsense combinations are errors naming the key.
#include <catch2/catch.hpp>

#include "config_test_base.hpp"
#include "sphmol/config/config.hpp"

using namespace config_test;
using Catch::Matchers::Contains;

namespace {
const std::string cavity = R"(case: cavity
fluid:
  density: 1
  kinematic_viscosity: 0.01
  eos:
    sound_speed: 10
geometry:
  box: [1, 1]
  wall_velocity: 1
discretization:
  particles_across: 20
time:
  t_end: 1
)";
// The same box without the lid: the tank of the hydrostatic case (which has no wall_velocity key).
const std::string tank = [] {
  std::string y = cavity;
  y.replace(y.find("case: cavity"), 12, "case: hydrostatic");
  y.erase(y.find("  wall_velocity: 1\n"), 19);
  return y;
}();
std::string set(const std::string& yaml, const std::vector<std::string>& o) { return error_of(yaml, o); }
}  // namespace

TEST_CASE("config: box cases, Tait and boundary keys load and round-trip", "[config]") {
  CHECK(error_of(cavity) == "<no error>");
  const auto c = sphmol::load_config_string(cavity, {"fluid.eos.type=tait", "fluid.eos.gamma=7.5", "fluid.eos.clamp_negative=true",
                                                     "discretization.boundary=ghost", "discretization.wall_slip=free_slip",
                                                     "fluid.body_force_ramp=0.5", "discretization.laplacian_correction=moment"});
  CHECK(c.discretization.laplacian_correction == "moment");
  CHECK(c.fluid.eos.gamma == 7.5);
  CHECK(c.fluid.eos.clamp_negative);
  CHECK(c.discretization.wall_model == "prescribed");
  CHECK(c.discretization.wall_slip == "free_slip");
  const auto back = sphmol::load_config_string(sphmol::to_yaml(c));
  CHECK(sphmol::to_yaml(back) == sphmol::to_yaml(c));
  const auto r = sphmol::load_config_string(tank, {"fluid.body_force=[0, -9.81]", "discretization.boundary=virtual_repulsive",
                                                     "discretization.repulsive.strength=8.8", "discretization.repulsive.p1=9.5"});
  CHECK(r.discretization.repulsive.strength == 8.8);
  CHECK(r.discretization.repulsive.p1 == 9.5);
  CHECK(r.discretization.repulsive.p2 == 4.0);
  CHECK(sphmol::to_yaml(sphmol::load_config_string(sphmol::to_yaml(r))) == sphmol::to_yaml(r));
  // The pair-symmetric moment correction loads and round-trips like `moment`.
  const auto s = sphmol::load_config_string(cavity, {"discretization.laplacian_correction=moment_symmetric"});
  CHECK(s.discretization.laplacian_correction == "moment_symmetric");
  CHECK(sphmol::load_config_string(sphmol::to_yaml(s)).discretization.laplacian_correction == "moment_symmetric");
}

TEST_CASE("config: nonsense boundary / EOS combinations are errors", "[config]") {
  CHECK_THAT(set(cavity, {"discretization.boundary=ghost", "discretization.wall_model=morris"}),
             Contains("discretization.wall_model: morris extrapolates"));
  CHECK_THAT(set(cavity, {"discretization.wall_slip=free_slip"}), Contains("applies to boundary: ghost only"));
  CHECK_THAT(set(cavity, {"discretization.boundary=virtual_repulsive"}), Contains("discretization.repulsive.strength"));
  CHECK_THAT(set(cavity, {"discretization.repulsive.strength=1"}), Contains("apply to boundary: virtual_repulsive only"));
  CHECK_THAT(set(tank, {"fluid.body_force=[0, -9.81]", "discretization.boundary=virtual_repulsive", "discretization.repulsive.strength=1",
                          "discretization.repulsive.p1=3"}),
             Contains("discretization.repulsive.p1: 3 is out of range"));
  CHECK_THAT(set(cavity, {"discretization.boundary=ghost", "discretization.wall_pressure=extrapolated"}),
             Contains("applies to boundary: wall_particles only"));
  CHECK_THAT(set(cavity, {"discretization.viscosity=strain_rate", "discretization.laplacian_correction=moment"}),
             Contains("discretization.laplacian_correction: corrects the Morris viscosity only"));
  CHECK_THAT(set(cavity, {"discretization.viscosity=strain_rate", "discretization.laplacian_correction=moment_symmetric"}),
             Contains("discretization.laplacian_correction: corrects the Morris viscosity only"));
  CHECK_THAT(set(cavity, {"discretization.laplacian_correction=tensor"}), Contains("allowed: none, moment, moment_symmetric"));
  CHECK_THAT(set(cavity, {"fluid.eos.gamma=7"}), Contains("only with type 'tait' or 'ideal_gas'"));
  CHECK_THAT(set(cavity, {"fluid.eos.clamp_negative=true"}), Contains("applies to type: tait only"));
  // Another case's geometry keys are unknown keys of this one.
  CHECK_THAT(set(cavity, {"case=taylor_green"}), Contains("geometry.wall_velocity: unknown key (allowed in geometry: box, velocity_amplitude)"));
  CHECK_THAT(set(base, {"discretization.boundary=ghost"}), Contains("'ghost' is not available for case 'couette'"));
  CHECK_THAT(set(cavity, {"geometry.wall_velocity=0"}), Contains("case 'cavity' needs a nonzero lid speed"));
  CHECK_THAT(set(cavity, {"geometry.box=[1]"}), Contains("geometry.box: has 1 components"));
  CHECK_THAT(set(cavity, {"geometry.channel_height=1"}), Contains("geometry.channel_height: unknown key (allowed in geometry: box, wall_velocity)"));
  CHECK_THAT(set(base, {"geometry.box=[1, 1]"}), Contains("geometry.box: unknown key (allowed in geometry: channel_height"));
  CHECK_THAT(set(cavity, {"fluid.body_force_ramp=-1"}), Contains("fluid.body_force_ramp: -1 is out of range"));
}

TEST_CASE("config: discretization.particle_mass: summation by default, gradient with continuity density only", "[config]") {
  std::string heavy = tank;  // the tank under gravity
  heavy.replace(heavy.find("    sound_speed: 10\n"), 20, "    sound_speed: 10\n  body_force: [0, -9.81]\n");
  const auto d = sphmol::load_config_string(heavy);
  CHECK(d.discretization.particle_mass == "summation");
  // The default is not written back (configs written before the key read the same).
  CHECK(sphmol::to_yaml(d).find("particle_mass") == std::string::npos);
  const auto c = sphmol::load_config_string(heavy, {"discretization.density=continuity", "discretization.particle_mass=gradient"});
  CHECK(c.discretization.particle_mass == "gradient");
  const auto back = sphmol::load_config_string(sphmol::to_yaml(c));
  CHECK(back.discretization.particle_mass == "gradient");
  CHECK(sphmol::to_yaml(back) == sphmol::to_yaml(c));
  CHECK(set(heavy, {"discretization.density=continuity", "discretization.particle_mass=summation"}) == "<no error>");
  // Summation density takes rho from the masses: the gradient mass would not give rho0. At its line.
  std::string summed = heavy;
  summed.replace(summed.find("  particles_across: 20\n"), 23, "  particles_across: 20\n  particle_mass: gradient\n");
  CHECK(set(summed, {}) ==
        "case.yaml:12: discretization.particle_mass: 'gradient' gives the lattice a summed density other than rho0; "
        "needs discretization.density: continuity (got 'summation')");
  CHECK_THAT(set(summed, {"discretization.density=normalised_summation"}),
             Contains("discretization.particle_mass") && Contains("(got 'normalised_summation')"));
  CHECK_THAT(set(heavy, {"discretization.density=continuity", "discretization.particle_mass=volume"}),
             Contains("discretization.particle_mass: unknown value 'volume'") && Contains("allowed: summation, gradient"));
  // Every lattice case takes it; the dam break (mass rho0 dx^2) and the shock tube set their own masses.
  for (const std::string& yaml : {cavity, heavy, base})
    CHECK(set(yaml, {"discretization.density=continuity", "discretization.particle_mass=gradient"}) == "<no error>");
  const std::string shock = std::string(SPHMOL_SOURCE_DIR) + "/verification/shock_tube.yaml";
  try {
    (void)sphmol::load_config(shock, {"discretization.density=continuity", "discretization.particle_mass=gradient"});
    FAIL("shock_tube accepted particle_mass: gradient");
  } catch (const sphmol::ConfigError& e) {
    CHECK_THAT(e.what(), Contains("discretization.particle_mass: is not applied by case 'shock_tube'"));
  }
}

TEST_CASE("config: discretization.bulk_viscosity: off by default, round-trips, in range, not for an ideal gas", "[config]") {
  const auto d = sphmol::load_config_string(cavity);
  CHECK(d.discretization.bulk_viscosity == 0.0);
  CHECK(sphmol::to_yaml(d).find("bulk_viscosity") == std::string::npos);
  const auto c = sphmol::load_config_string(cavity, {"discretization.bulk_viscosity=2"});
  CHECK(c.discretization.bulk_viscosity == 2.0);
  const auto back = sphmol::load_config_string(sphmol::to_yaml(c));
  CHECK(back.discretization.bulk_viscosity == 2.0);
  CHECK(sphmol::to_yaml(back) == sphmol::to_yaml(c));
  CHECK_THAT(set(cavity, {"discretization.bulk_viscosity=-1"}),
             Contains("discretization.bulk_viscosity: -1 is out of range") && Contains("zeta / (c0 h)"));
  CHECK_THAT(set(cavity, {"discretization.bulk_viscosity=.nan"}), Contains("discretization.bulk_viscosity"));
  // Ghost images carry the mirrored no-slip velocity, whose divergence is not the fluid's.
  CHECK_THAT(set(cavity, {"discretization.bulk_viscosity=1", "discretization.boundary=ghost"}),
             Contains("discretization.bulk_viscosity: not available with boundary 'ghost'"));
  CHECK(set(cavity, {"discretization.bulk_viscosity=1"}) == "<no error>");
  const std::string shock = std::string(SPHMOL_SOURCE_DIR) + "/verification/sod_1d.yaml";  // wall particles
  try {
    (void)sphmol::load_config(shock, {"discretization.bulk_viscosity=1"});
    FAIL("shock_tube accepted bulk_viscosity with an ideal gas");
  } catch (const sphmol::ConfigError& e) {
    CHECK_THAT(e.what(), Contains("discretization.bulk_viscosity") && Contains("ideal gas"));
  }
}
