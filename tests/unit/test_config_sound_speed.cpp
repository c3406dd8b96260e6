// The sound speed default: c = 10 U from the case's velocity scale when fluid.eos.sound_speed is not
// given (config/loader.cpp), with a notice; an error at the key for cases that give no velocity scale;
// an explicit value always wins. The same velocity scale is the default particle-shifting velocity.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>

#include "sphmol/config/config.hpp"
#include "config_test_base.hpp"

using namespace sphmol;
using config_test::has_notice;
using config_test::shipped;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

// `text` without its one line that contains `key`.
std::string without_line(std::string text, const std::string& key) {
  const auto at = text.find(key);
  REQUIRE(at != std::string::npos);
  const auto begin = text.rfind('\n', at) + 1, end = text.find('\n', at);
  return text.erase(begin, end - begin + 1);
}

}  // namespace

TEST_CASE("config: without sound_speed, c = 10 U from the case's velocity scale", "[config][sound_speed]") {
  // The shipped file gives no sound speed: it relies on this default.
  const std::string tg = shipped("taylor_green.yaml");
  REQUIRE(tg.find("sound_speed:") == std::string::npos);
  SECTION("taylor_green: U = geometry.velocity_amplitude") {
    const Config c = load_config_string(tg, {}, "tg.yaml");
    CHECK(c.fluid.eos.sound_speed == Approx(10.0));
    CHECK(has_notice(c, "fluid.eos.sound_speed: not given: c = 10 U = 10 m/s"));
    const Config slow = load_config_string(tg, {"geometry.velocity_amplitude=0.1"}, "tg.yaml");
    CHECK(slow.fluid.eos.sound_speed == Approx(1.0));
    // Written back explicitly, so the config.yaml of a run reproduces it.
    CHECK_THAT(to_yaml(slow), Contains("sound_speed: 1"));
  }
  SECTION("couette: U = the wall speed") {
    const Config c = load_config_string(config_test::with("    sound_speed: 0.01", "    type: linear"), {}, "case.yaml");
    CHECK(c.fluid.eos.sound_speed == Approx(1.25e-4));
  }
  SECTION("an explicit sound speed is kept") {
    const Config c = load_config_string(tg, {"geometry.velocity_amplitude=0.1", "fluid.eos.sound_speed=10"}, "tg.yaml");
    CHECK(c.fluid.eos.sound_speed == 10.0);
    CHECK_FALSE(has_notice(c, "sound_speed"));
  }
  SECTION("taken out by an override: the notice names the override") {
    const std::string cavity = shipped("cavity.yaml");
    const Config c = load_config_string(cavity, {"fluid.eos.sound_speed=null"}, "cavity.yaml");
    CHECK(has_notice(c, "--set fluid.eos.sound_speed=null: fluid.eos.sound_speed: not given: c = 10 U = 10 m/s"));
    // Not an earlier override of the same key, which the removal discarded.
    const Config d = load_config_string(cavity, {"fluid.eos.sound_speed=7", "fluid.eos.sound_speed=null"}, "cavity.yaml");
    CHECK(has_notice(d, "--set fluid.eos.sound_speed=null: fluid.eos.sound_speed: not given"));
    // A later override of a whole section replaces what earlier ones set inside it.
    const Config e = load_config_string(cavity, {"fluid.eos.sound_speed=7", "fluid.eos={type: linear}"}, "cavity.yaml");
    CHECK(has_notice(e, "--set fluid.eos={type: linear}: fluid.eos.sound_speed: not given"));
  }
  SECTION("cavity: U = |lid speed|, also for a lid along -x") {
    const std::string cavity = without_line(shipped("cavity.yaml"), "sound_speed:");
    const Config c = load_config_string(cavity, {}, "cavity.yaml");
    CHECK(c.fluid.eos.sound_speed == Approx(10.0));
    CHECK(has_notice(c, "fluid.eos.sound_speed: not given: c = 10 U = 10 m/s"));
    const Config fast = load_config_string(cavity, {"geometry.wall_velocity=-2"}, "cavity.yaml");
    CHECK(fast.fluid.eos.sound_speed == Approx(20.0));
  }
  SECTION("duct: U = |u_max| of the series, for either sign of g") {
    const std::string duct = without_line(shipped("duct_3d.yaml"), "sound_speed:");
    const Config plus = load_config_string(duct, {}, "duct.yaml");
    const Config minus = load_config_string(duct, {"fluid.body_force=[-2e-4, 0, 0]"}, "duct.yaml");
    // The square duct's centre speed 0.2947 g a^2 / nu (a the half-width; White 2006, eq 3-48).
    CHECK(plus.fluid.eos.sound_speed == Approx(10.0 * 0.2947 * 2e-4 * 0.25e-6 / 1e-6).epsilon(1e-3));
    CHECK(minus.fluid.eos.sound_speed == plus.fluid.eos.sound_speed);
  }
  SECTION("beltrami: U = sqrt(A^2 + B^2 + C^2)") {
    const std::string abc = without_line(shipped("beltrami_3d.yaml"), "sound_speed:");
    const Config c = load_config_string(abc, {"geometry.amplitudes=[-1, 2, 2]"}, "abc.yaml");
    CHECK(c.fluid.eos.sound_speed == Approx(30.0));
  }
  SECTION("a case without a velocity scale from its config still needs it") {
    const std::string dam = without_line(shipped("dam_break.yaml"), "sound_speed:");
    CHECK_THROWS_WITH(load_config_string(dam, {}, "dam_break.yaml"),
                      StartsWith("dam_break.yaml:") && Contains("fluid.eos.sound_speed: required value missing") &&
                          Contains("gives no velocity scale"));
  }
}

TEST_CASE("config: particle shifting takes the scene's velocity scale unless given", "[config][particle_shifting]") {
  // The shipped file without its position correction: a map given selects (position_correction absent).
  const std::string tg = without_line(without_line(shipped("taylor_green.yaml"), "position_correction:"), "transport_velocity:");
  const Config c = load_config_string(tg, {"discretization.particle_shifting={coefficient: 2}",
                                           "geometry.velocity_amplitude=0.5"}, "tg.yaml");
  REQUIRE(c.discretization.particle_shifting.enabled);
  CHECK(c.discretization.particle_shifting.coefficient == 2.0);
  CHECK(c.discretization.particle_shifting.velocity == Approx(0.5));
  const Config given = load_config_string(tg, {"discretization.particle_shifting={velocity: 3}"}, "tg.yaml");
  CHECK(given.discretization.particle_shifting.velocity == 3.0);
  CHECK(given.discretization.particle_shifting.coefficient == 4.0);
  // Round trip through to_yaml.
  const Config back = load_config_string(to_yaml(c), {}, "back.yaml");
  CHECK(back.discretization.particle_shifting.velocity == c.discretization.particle_shifting.velocity);
  CHECK(back.discretization.particle_shifting.coefficient == 2.0);
  CHECK(back.discretization.particle_shifting.correction);
  // Errors name the key.
  CHECK_THROWS_WITH(load_config_string(tg, {"discretization.particle_shifting={coefficient: 0}"}, "tg.yaml"),
                    Contains("discretization.particle_shifting.coefficient: 0 is out of range"));
  CHECK_THROWS_WITH(load_config_string(without_line(shipped("taylor_green.yaml"), "position_correction:"),
                                       {"discretization.particle_shifting={}"}, "tg.yaml"),
                    Contains("is an alternative to discretization.transport_velocity"));
  CHECK_THROWS_WITH(load_config_string(shipped("hydrostatic.yaml"), {"discretization.particle_shifting={velocity: 1}"}, "h.yaml"),
                    Contains("needs a flow without a free surface"));
}
