// The hydrostatic tank's defaults from its depth (cases/hydrostatic/hydrostatic_module.cpp): without
// discretization.particles_across or spacing, 36 rows in the depth (more when the width is then not a
// whole number of spacings); without fluid.eos.sound_speed, c0 = 20 sqrt(g H). Each with a notice,
// written back by to_yaml, and overridden by an explicit value. A user who changes only geometry.box
// gets the resolution and sound speed of the new depth, not the shipped tank's.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "sphmol/config/config.hpp"
#include "config_test_base.hpp"

using namespace sphmol;
using Catch::Matchers::Contains;
using config_test::has_notice;

namespace {

std::string shipped_tank() { return config_test::shipped("hydrostatic.yaml"); }

}  // namespace

TEST_CASE("hydrostatic: the resolution follows the depth unless given", "[config][hydrostatic]") {
  const std::string tank = shipped_tank();
  // The shipped file relies on both defaults.
  REQUIRE(tank.find("particles_across:") == std::string::npos);
  REQUIRE(tank.find("\n  spacing:") == std::string::npos);
  REQUIRE(tank.find("sound_speed:") == std::string::npos);
  struct Shape {
    std::string box;
    double spacing;
  };
  // [width, depth] -> H / N: 36 rows where the width is then whole (40, 144 and 12 across), else the
  // next count that makes it whole (0.7 m: 42 rows, 60 across).
  for (const Shape& k : {Shape{"[1.0, 0.9]", 0.9 / 36}, Shape{"[2.0, 0.5]", 0.5 / 36}, Shape{"[0.5, 1.5]", 1.5 / 36},
                         Shape{"[1.0, 0.7]", 0.7 / 42}}) {
    INFO(k.box);
    const Config c = load_config_string(tank, {"geometry.box=" + k.box}, "tank.yaml");
    CHECK(c.discretization.particles_across == 0);
    CHECK(c.discretization.spacing == Approx(k.spacing).epsilon(1e-12));
    CHECK(has_notice(c, "discretization.spacing: not given"));
    CHECK(has_notice(c, "rows in the depth"));
    // Written back, so a run's config.yaml reproduces it.
    const Config again = load_config_string(to_yaml(c), {}, "again.yaml");
    CHECK(again.discretization.spacing == c.discretization.spacing);
    CHECK_FALSE(has_notice(again, "not given"));
  }
  SECTION("an explicit resolution is kept") {
    const Config across = load_config_string(tank, {"geometry.box=[2.0, 0.5]", "discretization.particles_across=80"}, "tank.yaml");
    CHECK(across.discretization.particles_across == 80);
    CHECK(across.discretization.spacing == 0.0);
    CHECK_FALSE(has_notice(across, "discretization.spacing: not given"));
    const Config dx = load_config_string(tank, {"discretization.spacing=0.05"}, "tank.yaml");
    CHECK(dx.discretization.spacing == 0.05);
  }
  SECTION("no whole count from 36 to 72 rows: the error names the keys to give") {
    CHECK_THROWS_WITH(load_config_string(tank, {"geometry.box=[1.0, 0.777777]"}, "tank.yaml"),
                      Contains("discretization.particles_across: required value missing") &&
                          Contains("no number of rows in the depth 0.777777 m from 36 to 72"));
  }
  SECTION("3D: every side a whole number of the spacing") {
    const Config c = load_config_string(tank, {"dimension=3", "geometry.box=[0.5, 0.25, 0.5]", "fluid.body_force=[0, 0, -9.81]"},
                                        "tank.yaml");
    CHECK(c.discretization.spacing == Approx(0.5 / 36).epsilon(1e-12));
  }
  SECTION("other cases still need one of the two") {
    const std::string tg = "case: taylor_green\ndimension: 2\nfluid: {density: 1.0, kinematic_viscosity: 0.01}\n"
                           "geometry: {length: 1.0, velocity_amplitude: 1.0}\n"
                           "discretization: {kernel: wendland_c2}\ntime: {t_end: 0.1}\n";
    CHECK_THROWS_WITH(load_config_string(tg, {}, "tg.yaml"),
                      Contains("discretization.particles_across: required value missing"));
  }
}

TEST_CASE("hydrostatic: the sound speed follows the depth unless given", "[config][hydrostatic][sound_speed]") {
  const std::string tank = shipped_tank();
  for (const double depth : {0.5, 0.9, 1.5}) {
    const Config c = load_config_string(tank, {"geometry.box=[1.5, " + std::to_string(depth) + "]"}, "tank.yaml");
    INFO(depth);
    CHECK(c.fluid.eos.sound_speed == Approx(20.0 * std::sqrt(9.81 * depth)).epsilon(1e-12));
    CHECK(has_notice(c, "fluid.eos.sound_speed: not given: c = 20 sqrt(g H)"));
    CHECK_THAT(to_yaml(c), Contains("sound_speed: "));
  }
  // g from the body force, not a constant.
  const Config moon = load_config_string(tank, {"fluid.body_force=[0, -1.62]"}, "tank.yaml");
  CHECK(moon.fluid.eos.sound_speed == Approx(20.0 * std::sqrt(1.62 * 0.9)).epsilon(1e-12));
  const Config given = load_config_string(tank, {"fluid.eos.sound_speed=30"}, "tank.yaml");
  CHECK(given.fluid.eos.sound_speed == 30.0);
  CHECK_FALSE(has_notice(given, "sound_speed"));
}
