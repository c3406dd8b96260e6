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
