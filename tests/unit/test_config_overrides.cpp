// --set key.path=value overrides: applied to the YAML tree before validation; errors about
// overridden values name the override instead of a file line.
#include <catch2/catch.hpp>

#include "config_test_base.hpp"
#include "sphmol/config/config.hpp"

using namespace sphmol;
using config_test::base;
using config_test::error_of;
using config_test::with;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("config overrides: change scalars, lists and names", "[config]") {
  const Config c = load_config_string(
      base, {"time.rtol=1e-8", "output.times=[0.05, 0.25]", "discretization.kernel=cubic_spline",
             "fluid.density = 998.2", "output.profiles=false"});
  CHECK(c.time.rtol == 1e-8);
  CHECK(c.output.times == std::vector<double>{0.05, 0.25, 0.5});
  CHECK(c.discretization.kernel == "cubic_spline");
  CHECK(c.fluid.density == 998.2);
  CHECK_FALSE(c.output.profiles);
  // Untouched values keep the file's.
  CHECK(c.fluid.kinematic_viscosity == 1.0e-6);
  CHECK(c.discretization.particles_across == 20);
}

TEST_CASE("config overrides: create keys and sections the file does not have", "[config]") {
  const Config c = load_config_string(base, {"time.dt=1e-5", "time.cfl.acoustic=0.1", "time.cfl={force: 0.2}"});
  REQUIRE(c.time.dt.has_value());
  CHECK(*c.time.dt == 1e-5);
  // Applied in order: the later map replaces the whole cfl section.
  CHECK(c.time.cfl.force == 0.2);
  CHECK(c.time.cfl.acoustic == 0.25);
  // The whole config from overrides alone.
  const Config p = load_config_string(
      "", {"case=poiseuille", "fluid.density=1000", "fluid.kinematic_viscosity=1e-6", "fluid.eos.sound_speed=1",
           "fluid.body_force=[1e-4, 0]", "geometry.channel_height=1e-3", "geometry.channel_length=1e-3",
           "discretization.spacing=5e-5", "time.t_end=1"});
  CHECK(p.case_name == "poiseuille");
  CHECK(p.discretization.spacing == 5e-5);
  CHECK(p.output.times == std::vector<double>{1.0});
}

TEST_CASE("config overrides: errors name the override", "[config]") {
  CHECK(error_of(base, {"time.rtl=1e-8"}) ==
        "--set time.rtl=1e-8: time.rtl: unknown key (did you mean 'rtol'? allowed in time: t_end, integrator, "
        "table, rtol, atol, cfl, dt, max_steps, krylov)");
  CHECK_THAT(error_of(base, {"fluids.density=1"}),
             StartsWith("--set fluids.density=1: fluids: unknown key (did you mean 'fluid'?"));
  CHECK(error_of(base, {"time.rtol=-1"}) == "--set time.rtol=-1: time.rtol: -1 is out of range (allowed: >= 1e-15, the double round-off)");
  CHECK(error_of(base, {"output.times=[0.3, 0.2]"}) ==
        "--set output.times=[0.3, 0.2]: output.times[1]: 0.2 is not after the previous time 0.3 (times must be "
        "strictly increasing)");
  CHECK(error_of(base, {"discretization.kernel=wendland"}) ==
        "--set discretization.kernel=wendland: discretization.kernel: unknown value 'wendland' (allowed: cubic_spline, lucy, gaussian, truncated_exponential, quartic_liu, quintic_morris, quadratic_johnson, super_gaussian, desbrun_spiky, muller_poly6, composite, wendland_c2)");
  CHECK(error_of(base, {"output.times=0.3"}) ==
        "--set output.times=0.3: output.times: expected a list of numbers such as [0.1, 0.2], got '0.3'");
  CHECK(error_of(base, {"discretization.spacing=1e-4"}) ==
        "--set discretization.spacing=1e-4: discretization.spacing: both particles_across and spacing are given "
        "(allowed: exactly one of them)");
  CHECK(error_of(base, {"time.rtol"}) ==
        "--set time.rtol: malformed override: expected key.path=value (e.g. time.rtol=1e-8)");
  CHECK_THAT(error_of(base, {"time..rtol=1"}), StartsWith("--set time..rtol=1: malformed override: empty key"));
  CHECK_THAT(error_of(base, {"=1"}), StartsWith("--set =1: malformed override: empty key"));
  CHECK(error_of(base, {"time.t_end.x=1"}) ==
        "--set time.t_end.x=1: time.t_end.x: 'time.t_end' is not a section, cannot set keys inside it");
  // Absent from the file: the override creates a section where a number belongs.
  CHECK(error_of(base, {"time.rtol.x=1"}) == "--set time.rtol.x=1: time.rtol: expected a number, got a map");
  CHECK_THAT(error_of(base, {"output.times=[0.1,"}),
             StartsWith("--set output.times=[0.1,: output.times: YAML syntax error in the value: "));
  // Errors in the file keep pointing at the file even when overrides are given.
  CHECK(error_of(with("density: 1000", "density: -1"), {"time.rtol=1e-8"}) ==
        "case.yaml:4: fluid.density: -1 is out of range (allowed: > 0 kg/m^3)");
  // ... and an override fixes a bad file value.
  CHECK(error_of(with("density: 1000", "density: -1"), {"fluid.density=1000"}) == "<no error>");
}

TEST_CASE("config overrides: key=null removes the key", "[config]") {
  // Swap the resolution keys, and take a fixed step out.
  const Config c = load_config_string(base, {"discretization.particles_across=null", "discretization.spacing=5e-5",
                                             "time.dt=1e-5", "time.dt=~"});
  CHECK(c.discretization.spacing == 5e-5);
  CHECK_FALSE(c.time.dt.has_value());
  // A key or section that is not there: nothing to do, nothing created.
  const Config d = load_config_string(base, {"time.table=null", "health.max_outflow_fraction=null"});
  CHECK(d.time.table == Config{}.time.table);
}
