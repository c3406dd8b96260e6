// Study helpers: integrator lists, nominal orders from the SUNDIALS tables, observed-order
// arithmetic, and the stability classification.
#include <catch2/catch.hpp>

#include <cmath>

#include "sphmol/studies/converge.hpp"
#include "sphmol/studies/integrator_spec.hpp"
#include "sphmol/studies/stability.hpp"

using namespace sphmol;

TEST_CASE("integrator lists parse, and ERK orders come from the tables", "[studies]") {
  const auto s = parse_integrator_list("leapfrog,arkode_erk:ARKODE_BOGACKI_SHAMPINE_4_2_3,arkode_erk,cvode_adams", "ARKODE_HEUN_EULER_2_1_2");
  REQUIRE(s.size() == 4);
  CHECK(s[0].order() == 2);
  CHECK(s[1].order() == 3);
  CHECK(s[2].table == "ARKODE_HEUN_EULER_2_1_2");
  CHECK(s[2].order() == 2);
  CHECK(s[3].adaptive());
  CHECK_FALSE(s[0].adaptive());
  CHECK(erk_table_order("ARKODE_DORMAND_PRINCE_7_4_5") == 5);
  CHECK(erk_table_order("ARKODE_VERNER_8_5_6") == 6);
  CHECK_THROWS(parse_integrator_list("rk4", ""));
  CHECK_THROWS(parse_integrator_list("arkode_erk:NOPE", ""));
  CHECK_THROWS(parse_integrator_list("leapfrog:X", ""));
}

TEST_CASE("observed orders: pairwise and least squares", "[studies]") {
  const std::vector<double> e{1.0, 0.25, 0.0625, 0.015625};
  for (double p : pairwise_orders(e)) CHECK(p == Approx(2.0));
  CHECK(least_squares_order(e) == Approx(2.0));
  CHECK(least_squares_order({8.0, 1.0}) == Approx(3.0));
}

TEST_CASE("stability classification", "[studies]") {
  auto summary = [](std::vector<double> s, const char* status = "completed") {
    nlohmann::json j{{"status", status}, {"errors", nlohmann::json::array()}};
    for (double x : s) j["errors"].push_back({{"e_signed", x}});
    return j;
  };
  CHECK(classify_run(summary({0.1, 0.05, 0.02, 0.005}), 0.01).label == "stable");
  CHECK(classify_run(summary({0.1, -0.05, 0.03, -0.02}), 0.01).label == "oscillating");
  CHECK(classify_run(summary({0.1, -0.05, 0.03, -0.02}), 0.01).sign_changes == 3);
  CHECK(classify_run(summary({0.1, -0.005, 0.003, 0.02}), 0.01).label == "stable");  // small wiggles ignored
  CHECK(classify_run(summary({}, "blown_up"), 0.01).label == "blown_up");
  CHECK(classify_run(summary({0.1, -3.0, 40.0, -200.0}), 0.01).label == "blown_up");  // unbounded growth
}
