// Convergence orders in CI. Time: a short, coarse Couette run (20 particles across, t_end = 0.01 s,
// fixed steps 5e-4 / 2^k: the error is the time error of the same discretisation, measured against a
// Verner-6 run at dt/8, and lies between 1e-4 and 1e-11, above round-off). Space: Poiseuille at 10,
// 20, 40 particles across with the time error negligible. Reports under the build tree (reports/).
#include <catch2/catch.hpp>

#include <fstream>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/studies/converge.hpp"

using namespace sphmol;

TEST_CASE("time convergence on Couette: observed orders reach the nominal ones", "[integration][convergence]") {
  Config c = load_config(SPHMOL_SOURCE_DIR "/verification/couette.yaml",
                         {"discretization.particles_across=20", "time.t_end=0.01", "output.times=[0.01]"});
  ConvergeOptions o;
  o.refine = "time";
  o.levels = 4;
  o.dt0 = 5e-4;
  o.integrators = parse_integrator_list(
      "leapfrog,leapfrog_kdk,arkode_erk:ARKODE_HEUN_EULER_2_1_2,arkode_erk:ARKODE_BOGACKI_SHAMPINE_4_2_3", "");
  o.output_dir = "reports/convergence_time_couette";
  const auto j = run_converge(c, o);
  REQUIRE(j["series"].size() == 4);
  for (const auto& s : j["series"]) {
    const double expected = s["expected_order"].get<double>();
    INFO(s["integrator"].get<std::string>() << ": errors " << s["errors"].dump() << ", orders " << s["observed_orders"].dump());
    CHECK(s["observed_order"].get<double>() >= expected - 0.2);
    for (const auto& p : s["observed_orders"]) CHECK(p.get<double>() >= expected - 0.2);
    CHECK(s["errors"].back().get<double>() > 1e-13);  // still above round-off
  }
}

TEST_CASE("space convergence on Poiseuille: the error decreases monotonically over three levels", "[integration][convergence]") {
  Config c = load_config(SPHMOL_SOURCE_DIR "/verification/poiseuille.yaml",
                         {"discretization.particles_across=10", "geometry.channel_length=1.0e-3", "time.t_end=0.1",
                          "output.times=[0.1]"});
  ConvergeOptions o;
  o.refine = "space";
  o.levels = 3;
  o.output_dir = "reports/convergence_space_poiseuille";
  const auto j = run_converge(c, o);
  // Space refinement lists the spacings the scenes used, under a key that says so.
  CHECK(j["series"][0]["spacings"].size() == 3);
  CHECK_FALSE(j["series"][0].contains("steps"));
  const auto e = j["series"][0]["errors"].get<std::vector<double>>();
  INFO("errors " << j["series"][0]["errors"].dump());
  REQUIRE(e.size() == 3);
  CHECK(e[1] < e[0]);
  CHECK(e[2] < e[1]);
}

namespace {
// Poiseuille 20 across to t = 0.1 s at fixed steps 0.005 / 2^k (4 levels), one integrator.
nlohmann::json poiseuille_time(const std::string& integrators, const std::string& out, std::vector<std::string> sets = {}) {
  sets.insert(sets.end(), {"discretization.particles_across=20", "time.t_end=0.1", "output.times=[0.1]"});
  Config c = load_config(SPHMOL_SOURCE_DIR "/verification/poiseuille.yaml", sets);
  ConvergeOptions o;
  o.refine = "time";
  o.levels = 4;
  o.dt0 = 0.005;
  o.integrators = parse_integrator_list(integrators, "");
  o.output_dir = out;
  return run_converge(c, o);
}
}  // namespace

TEST_CASE("time convergence with arkode_imex: the stage solves are tight enough to measure the order", "[integration][convergence][imex]") {
  // At the default time.rtol 1e-6 the stage solves' error (near 1e-8) hid the step's: orders 1.8 and -0.3.
  const auto j = poiseuille_time("arkode_imex,arkode_imex:ARKODE_ARK436L2SA_ERK_6_3_4", "reports/convergence_time_imex");
  REQUIRE(j["series"].size() == 2);
  for (const auto& s : j["series"]) {
    INFO(s["integrator"].get<std::string>() << ": errors " << s["errors"].dump() << ", orders " << s["observed_orders"].dump());
    CHECK(s["stage_solves"]["rtol"].get<double>() <= 1e-12);
    for (const auto& p : s["observed_orders"]) CHECK(p.get<double>() >= 2.7);  // ARK4(3)6: 2.9-3.5 here
    CHECK(s["observed_order"].get<double>() >= 2.8);
    CHECK(s["order_levels"] == nlohmann::json({0, 3}));
  }
  // A time.rtol the user gave is kept; the levels whose error is below the solves' tolerance are named
  // and left out of the order.
  const auto given = poiseuille_time("arkode_imex", "reports/convergence_time_imex_given", {"time.integrator=arkode_imex", "time.rtol=1e-6"});
  const auto& s = given["series"][0];
  CHECK(s["stage_solves"]["rtol"].get<double>() == 1e-6);
  CHECK(s["stage_solves"]["below_tolerance"] == nlohmann::json({true, true, true, true}));
  CHECK(s["observed_order"].is_null());
}

TEST_CASE("time convergence: blown-up levels have a status and the order comes from the clean ones", "[integration][convergence]") {
  // Bogacki-Shampine blows up at 0.005 and 0.0025 s (above its stability limit) and converges below.
  const std::string out = "reports/convergence_time_blown_up";
  const auto j = poiseuille_time("arkode_erk:ARKODE_BOGACKI_SHAMPINE_4_2_3", out);
  const auto& s = j["series"][0];
  INFO(s.dump());
  CHECK(s["status"] == nlohmann::json({"blown_up", "blown_up", "completed", "completed"}));
  CHECK(s["errors"][0].is_null());
  CHECK(s["observed_orders"][0].is_null());
  CHECK(s["observed_orders"][1].is_null());
  CHECK(s["observed_orders"][2].get<double>() > 2.8);
  CHECK(s["observed_order"].get<double>() > 2.8);
  CHECK(s["order_levels"] == nlohmann::json({2, 3}));
  // The CSV: a status column, and empty cells where the JSON has null (no "inf", no "nan").
  std::ifstream f(out + "/convergence.csv");
  std::string header, row;
  std::getline(f, header);
  CHECK(header.substr(header.size() - 7) == ",status");
  std::getline(f, row);
  const std::string start = "time,arkode_erk:ARKODE_BOGACKI_SHAMPINE_4_2_3,0,0.005,,,3,";  // error and order empty
  CHECK(row.substr(0, start.size()) == start);
  CHECK(row.substr(row.size() - 9) == ",blown_up");
  for (std::string line; std::getline(f, line);) {
    CHECK(line.find("inf") == std::string::npos);
    CHECK(line.find("nan") == std::string::npos);
  }
}
