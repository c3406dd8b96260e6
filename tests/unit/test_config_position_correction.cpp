// discretization.position_correction (config/loader.cpp, config/position_correction.hpp): auto takes the
// transport velocity below the cell Reynolds number threshold and particle shifting at or above it,
// Re_h = U h / nu from the case's velocity scale; explicit settings win over auto, contradictions are
// errors at the key that contradicts, and files without the key keep their meaning.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "config_test_base.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/config/position_correction.hpp"

using namespace sphmol;
using config_test::has_notice;
using config_test::shipped;
using Catch::Matchers::Contains;

namespace {

const std::string tg_path = std::string(SPHMOL_SOURCE_DIR) + "/verification/taylor_green.yaml";

std::string error_of(const std::string& path, const std::vector<std::string>& overrides) {
  try {
    (void)load_config(path, overrides);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "<no error>";
}

// The kinematic viscosity that puts the shipped Taylor-Green file (U = 1, 50 across, h = 2 dx = 0.04)
// at cell Reynolds number `re_h`.
std::string nu_for(double re_h) {
  std::ostringstream s;
  s.precision(17);
  s << "fluid.kinematic_viscosity=" << 1.0 * 0.04 / re_h;
  return s.str();
}

// `text` without its one line that contains `key`.
std::string without_line(std::string text, const std::string& key) {
  const auto at = text.find(key);
  REQUIRE(at != std::string::npos);
  const auto begin = text.rfind('\n', at) + 1, end = text.find('\n', at);
  return text.erase(begin, end - begin + 1);
}

}  // namespace

TEST_CASE("position correction rule: transport velocity below the cell Reynolds number threshold, shifting above",
          "[config][position_correction]") {
  const double t = kPositionCorrectionCellReynolds;
  CHECK(position_correction_for(0.0) == "transport_velocity");
  CHECK(position_correction_for(0.99 * t) == "transport_velocity");
  CHECK(position_correction_for(t) == "particle_shifting");
  CHECK(position_correction_for(100.0 * t) == "particle_shifting");
  CHECK(cell_reynolds_number(2.0, 0.5, 0.1) == Approx(10.0));
  // Inviscid: no viscosity to outweigh the shift's damping.
  CHECK(std::isinf(cell_reynolds_number(1.0, 0.1, 0.0)));
  CHECK(position_correction_for(cell_reynolds_number(1.0, 0.1, 0.0)) == "particle_shifting");
}

TEST_CASE("position_correction: auto in the shipped Taylor-Green file", "[config][position_correction]") {
  SECTION("Re 100 at 50 across: Re_h = 4, the transport velocity with the file's step factor") {
    const Config c = load_config(tg_path);
    const auto& d = c.discretization;
    CHECK(d.position_correction.setting == "auto");
    CHECK(d.position_correction.chosen == "transport_velocity");
    CHECK(d.position_correction.cell_reynolds == Approx(4.0));
    CHECK(d.transport_velocity.enabled);
    CHECK(d.transport_velocity.step_factor == 0.125);
    CHECK_FALSE(d.particle_shifting.enabled);
    CHECK(has_notice(c, "discretization.position_correction: auto: transport_velocity (Re_h = U h / nu = 1 * 0.04 / 0.01 = "));
    CHECK(has_notice(c, " < "));
  }
  SECTION("Re 1000 at 50 across: Re_h = 40, particle shifting with A = 4 and U from the case") {
    const Config c = load_config(tg_path, {"fluid.kinematic_viscosity=0.001"});
    const auto& d = c.discretization;
    CHECK(d.position_correction.chosen == "particle_shifting");
    CHECK(d.position_correction.cell_reynolds == Approx(40.0));
    CHECK(d.particle_shifting.enabled);
    CHECK(d.particle_shifting.coefficient == 4.0);
    CHECK(d.particle_shifting.velocity == Approx(1.0));
    CHECK_FALSE(d.transport_velocity.enabled);
    CHECK(has_notice(c, "auto: particle_shifting (Re_h = U h / nu = 1 * 0.04 / 0.001 = "));
    CHECK(has_notice(c, " >= "));
  }
  SECTION("either side of the threshold, and the resolution and U enter through Re_h") {
    const double t = kPositionCorrectionCellReynolds;
    CHECK(load_config(tg_path, {nu_for(0.9 * t)}).discretization.position_correction.chosen == "transport_velocity");
    CHECK(load_config(tg_path, {nu_for(1.1 * t)}).discretization.position_correction.chosen == "particle_shifting");
    // Half the spacing halves Re_h; half the velocity too.
    CHECK(load_config(tg_path, {nu_for(1.5 * t), "discretization.particles_across=100"})
              .discretization.position_correction.chosen == "transport_velocity");
    CHECK(load_config(tg_path, {nu_for(1.5 * t), "geometry.velocity_amplitude=0.5"})
              .discretization.position_correction.chosen == "transport_velocity");
  }
  SECTION("a map's stated `enabled` is an explicit choice and wins over the rule") {
    // The overrides of scripts/taylor_green_re_sweep.py: shifting at Re 100.
    const Config ps = load_config(tg_path, {"discretization.transport_velocity.enabled=false",
                                            "discretization.particle_shifting={coefficient: 4}"});
    CHECK(ps.discretization.particle_shifting.enabled);
    CHECK_FALSE(ps.discretization.transport_velocity.enabled);
    CHECK(ps.discretization.position_correction.reason == "discretization.transport_velocity.enabled: false was given");
    CHECK(ps.discretization.position_correction.cell_reynolds < 0.0);  // the rule was not asked
    // The transport velocity kept at Re 1000.
    const Config tv = load_config(tg_path, {"fluid.kinematic_viscosity=0.001", "discretization.transport_velocity.enabled=true"});
    CHECK(tv.discretization.transport_velocity.enabled);
    CHECK(tv.discretization.transport_velocity.step_factor == 0.125);
    CHECK_FALSE(tv.discretization.particle_shifting.enabled);
    const Config off = load_config(tg_path, {"fluid.kinematic_viscosity=0.001", "discretization.particle_shifting={enabled: false}"});
    CHECK(off.discretization.transport_velocity.enabled);
    // A parameter alone does not choose: A = 2 is used only if the rule picks shifting.
    const Config a2 = load_config(tg_path, {"discretization.particle_shifting={coefficient: 2}"});
    CHECK(a2.discretization.transport_velocity.enabled);
    const Config a2hi = load_config(tg_path, {"fluid.kinematic_viscosity=0.001", "discretization.particle_shifting={coefficient: 2}"});
    CHECK(a2hi.discretization.particle_shifting.enabled);
    CHECK(a2hi.discretization.particle_shifting.coefficient == 2.0);
  }
  SECTION("a named scheme wins over the rule") {
    const Config tv = load_config(tg_path, {"fluid.kinematic_viscosity=0.001", "discretization.position_correction=transport_velocity"});
    CHECK(tv.discretization.transport_velocity.enabled);
    CHECK(tv.discretization.transport_velocity.step_factor == 0.125);
    CHECK_FALSE(tv.discretization.particle_shifting.enabled);
    const Config ps = load_config(tg_path, {"discretization.position_correction=particle_shifting"});
    CHECK(ps.discretization.particle_shifting.enabled);
    CHECK_FALSE(ps.discretization.transport_velocity.enabled);  // the file's map is only its parameters
    const Config none = load_config(tg_path, {"discretization.position_correction=none"});
    CHECK_FALSE(none.discretization.particle_shifting.enabled);
    CHECK_FALSE(none.discretization.transport_velocity.enabled);
    CHECK_FALSE(has_notice(none, "position_correction: "));  // no choice to report
    // The file's transport-velocity parameters are not used, and the run says so.
    CHECK(has_notice(none, "transport_velocity.step_factor: not used: position_correction none"));
  }
  SECTION("written back as the choice, which loads to the same scheme and parameters") {
    const Config a = load_config(tg_path, {"fluid.kinematic_viscosity=0.001"});
    const std::string y = to_yaml(a);
    CHECK_THAT(y, Contains("# position_correction: auto chose particle_shifting: Re_h = "));
    CHECK_THAT(y, Contains("\n  position_correction: particle_shifting\n"));
    const Config b = load_config_string(y, {}, "back.yaml");
    CHECK(b.discretization.position_correction.chosen == "particle_shifting");
    CHECK(b.discretization.particle_shifting.enabled);
    CHECK(b.discretization.particle_shifting.coefficient == a.discretization.particle_shifting.coefficient);
    CHECK(b.discretization.particle_shifting.velocity == a.discretization.particle_shifting.velocity);
    CHECK_FALSE(b.discretization.transport_velocity.enabled);
    const Config c = load_config(tg_path);
    const Config d = load_config_string(to_yaml(c), {}, "back.yaml");
    CHECK(d.discretization.transport_velocity.enabled);
    CHECK(d.discretization.transport_velocity.step_factor == 0.125);
  }
}

TEST_CASE("position_correction: contradictions are errors at the key", "[config][position_correction]") {
  CHECK_THAT(error_of(tg_path, {"discretization.position_correction=transport_velocity",
                                "discretization.particle_shifting={enabled: true}"}),
             Contains("discretization.particle_shifting.enabled: true conflicts with discretization.position_correction: "
                      "transport_velocity"));
  CHECK_THAT(error_of(tg_path, {"discretization.position_correction=transport_velocity",
                                "discretization.transport_velocity.enabled=false"}),
             Contains("discretization.transport_velocity.enabled: false conflicts with discretization.position_correction: "
                      "transport_velocity"));
  CHECK_THAT(error_of(tg_path, {"discretization.position_correction=particle_shifting",
                                "discretization.particle_shifting={enabled: false}"}),
             Contains("discretization.particle_shifting.enabled: false conflicts"));
  CHECK_THAT(error_of(tg_path, {"discretization.position_correction=none", "discretization.transport_velocity.enabled=true"}),
             Contains("discretization.transport_velocity.enabled: true conflicts with discretization.position_correction: none"));
  CHECK_THAT(error_of(tg_path, {"discretization.transport_velocity.enabled=true", "discretization.particle_shifting={enabled: true}"}),
             Contains("discretization.particle_shifting.enabled: true together with discretization.transport_velocity.enabled: true"));
  CHECK_THAT(error_of(tg_path, {"discretization.transport_velocity.enabled=false", "discretization.particle_shifting={enabled: false}"}),
             Contains("discretization.position_correction: auto has nothing to choose from"));
  CHECK_THAT(error_of(tg_path, {"discretization.position_correction=sometimes"}),
             Contains("discretization.position_correction") && Contains("auto, transport_velocity, particle_shifting, none"));
}

TEST_CASE("position_correction: auto needs a velocity scale, the chosen scheme still needs its flow",
          "[config][position_correction]") {
  // The dam break's velocity scale sqrt(2 g H) is the built scene's, not known from its config alone.
  CHECK_THAT(config_test::error_of(shipped("dam_break.yaml"), {"discretization.position_correction=auto"}),
             Contains("discretization.position_correction: auto chooses by the cell Reynolds number") &&
                 Contains("gives no velocity scale U from its config"));
  // The cavity's is its lid speed |U|: Re_h = 1 * (2 / 40) / 0.01 = 5.
  const std::string cavity = without_line(shipped("cavity.yaml"), "transport_velocity:");
  const Config c = load_config_string(cavity, {"discretization.position_correction=auto", "geometry.wall_velocity=-1"},
                                      "cavity.yaml");
  CHECK(c.discretization.position_correction.cell_reynolds == Approx(5.0));
  CHECK(has_notice(c, "discretization.position_correction: auto:"));
  // A free surface: neither scheme, whichever key selects it.
  const std::string tank = shipped("hydrostatic.yaml");
  CHECK_THAT(config_test::error_of(tank, {"discretization.position_correction=particle_shifting"}),
             Contains("discretization.position_correction: 'particle_shifting': particle shifting needs a flow without a "
                      "free surface"));
  CHECK_THAT(config_test::error_of(tank, {"discretization.position_correction=transport_velocity"}),
             Contains("discretization.position_correction: 'transport_velocity': the transport velocity needs a confined liquid"));
}

TEST_CASE("position_correction absent: the maps select as before", "[config][position_correction]") {
  // The cavity files give the transport velocity explicitly and no position_correction.
  for (const char* name : {"cavity.yaml", "cavity_re400.yaml", "cavity_re1000.yaml"}) {
    const std::string text = shipped(name);
    INFO(name);
    REQUIRE(text.find("position_correction") == std::string::npos);
    const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/" + name);
    CHECK(c.discretization.position_correction.setting.empty());
    CHECK(c.discretization.position_correction.chosen == "transport_velocity");
    CHECK(c.discretization.transport_velocity.enabled);
    CHECK_FALSE(c.discretization.particle_shifting.enabled);
    CHECK_THAT(to_yaml(c), !Contains("position_correction"));
  }
  // Without the key, two maps are two choices: an error, as it always was.
  const std::string couette = config_test::with("  particles_across: 20",
                                                "  particles_across: 20\n  transport_velocity: {}\n  particle_shifting: {}");
  CHECK_THAT(config_test::error_of(couette), Contains("is an alternative to discretization.transport_velocity"));
  const Config none = load_config_string(config_test::base, {}, "case.yaml");
  CHECK(none.discretization.position_correction.chosen == "none");
  CHECK_FALSE(none.discretization.transport_velocity.enabled);
}
