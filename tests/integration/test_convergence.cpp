// Convergence orders in CI. Time: a short, coarse Couette run (20 particles across, t_end = 0.01 s,
// fixed steps 5e-4 / 2^k: the error is the time error of the same discretisation, measured against a
// Verner-6 run at dt/8, and lies between 1e-4 and 1e-11, above round-off). Space: Poiseuille at 10,
// 20, 40 particles across with the time error negligible. Reports under the build tree (reports/).
#include <catch2/catch.hpp>

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
  const auto e = j["series"][0]["errors"].get<std::vector<double>>();
  INFO("errors " << j["series"][0]["errors"].dump());
  REQUIRE(e.size() == 3);
  CHECK(e[1] < e[0]);
  CHECK(e[2] < e[1]);
}
