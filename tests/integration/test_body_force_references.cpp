// The references of the cases driven by a body force follow the force as configured: ramped in over
// fluid.body_force_ramp (Duhamel's principle, reference/ramped_start.hpp), or added to a moving plate
// (the channel is linear: the Couette and Poiseuille series add). Cases whose reference has no body
// force, or a force at full strength from t = 0 with no closed form otherwise, refuse one.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "in_process_run.hpp"

using namespace sphmol;

namespace {

std::string verification(const std::string& name) { return std::string(SPHMOL_SOURCE_DIR) + "/verification/" + name; }

nlohmann::json run(const std::string& file, const std::vector<std::string>& overrides) {
  return in_process::run_verification(file, overrides);
}

double e_rms_at(const nlohmann::json& s, double t) {
  for (const auto& e : s["errors"])
    if (e["t"].get<double>() == t) return e["e_rms"].get<double>();
  FAIL("no error at t = " << t);
  return 0.0;
}

std::string refusal(const std::string& file, std::vector<std::string> overrides) {
  try {
    load_config(verification(file), overrides);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("poiseuille with a ramped body force is measured against the ramped start-up", "[integration][poiseuille]") {
  // 20 across, ramp 0.02 s (l^2 / nu = 1 s). Against the series of the force at once, as before, e_rms
  // was 0.046 at t = 0.05 s and 0.028 at 0.1 s, where the run without a ramp has 0.0016 and 0.0019.
  const std::vector<std::string> common = {"discretization.particles_across=20", "time.t_end=0.1", "output.times=[0.05, 0.1]"};
  auto with = [&](const std::string& ramp) {
    auto o = common;
    o.push_back("fluid.body_force_ramp=" + ramp);
    return run("poiseuille.yaml", o);
  };
  const auto at_once = with("0"), ramped = with("0.02");
  INFO(ramped["errors"].dump());
  for (double t : {0.05, 0.1}) {
    CHECK(e_rms_at(ramped, t) < 1.2 * e_rms_at(at_once, t));
    CHECK(e_rms_at(ramped, t) < 0.003);
  }
  CHECK(ramped["reference"].get<std::string>().find("ramped in over fluid.body_force_ramp") != std::string::npos);
}

TEST_CASE("couette with a body force is measured against the Couette plus Poiseuille series", "[integration][couette]") {
  // F = 1e-4 m/s^2 adds a Poiseuille flow of peak 1.25e-5 m/s to the plate's 2.5e-5 m/s: against the
  // Couette series alone e_rms was 0.142 at t = 0.05 s.
  const std::vector<std::string> common = {"discretization.particles_across=20", "time.t_end=0.05", "output.times=[0.05]"};
  auto with = [&](const std::string& f) {
    auto o = common;
    o.push_back("fluid.body_force=[" + f + ", 0]");
    return run("couette.yaml", o);
  };
  const auto plate = with("0"), both = with("1e-4");
  INFO(both["final_errors"].dump());
  CHECK(both["final_errors"]["e_rms"].get<double>() < 1.2 * plate["final_errors"]["e_rms"].get<double>());
  CHECK(both["final_errors"]["e_rms"].get<double>() < 0.003);
  CHECK(both["reference"].get<std::string>().find("plus the Poiseuille start-up series") != std::string::npos);
}

TEST_CASE("duct with a ramped body force is measured against the ramped start-up", "[integration][duct]") {
  // 8 across, ramp 0.01 s = t_end: e_rms 0.0498 against the series of the force at once, 0.0036 now
  // (0.0106 without a ramp, whose start is more abrupt).
  const std::vector<std::string> common = {"discretization.particles_across=8", "geometry.length=1e-3", "time.t_end=0.01",
                                           "output.times=[0.005, 0.01]", "fluid.body_force_ramp=0.01"};
  const auto s = run("duct_3d.yaml", common);
  INFO(s["final_errors"].dump());
  CHECK(s["final_errors"]["e_rms"].get<double>() < 0.006);
  CHECK(s["reference"].get<std::string>().find("ramped in over fluid.body_force_ramp") != std::string::npos);
}

TEST_CASE("cases whose reference has no body force, or only a sudden one, refuse what they cannot follow", "[integration][config]") {
  CHECK_THAT(refusal("dam_break.yaml", {"fluid.body_force_ramp=0.1"}),
             Catch::Contains("body_force_ramp") && Catch::Contains("released under full gravity at t = 0"));
  CHECK_THAT(refusal("taylor_green.yaml", {"fluid.body_force=[0.01, 0]"}),
             Catch::Contains("fluid.body_force") && Catch::Contains("must be zero for case 'taylor_green'"));
  CHECK_THAT(refusal("shock_tube_1d.yaml", {"fluid.body_force=[0.01]"}),
             Catch::Contains("must be zero for case 'shock_tube'"));
  CHECK_THAT(refusal("beltrami_3d.yaml", {"fluid.body_force=[0.01, 0, 0]"}), Catch::Contains("must be zero for case 'beltrami'"));
  // A ramp of no force: said, not refused.
  const Config c = load_config(verification("taylor_green.yaml"), {"fluid.body_force_ramp=0.1"});
  bool said = false;
  for (const auto& n : c.notices) said = said || n.find("body_force_ramp: has no effect: fluid.body_force is zero") != std::string::npos;
  CHECK(said);
}
