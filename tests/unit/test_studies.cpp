// Study helpers: integrator lists, nominal orders from the SUNDIALS tables, observed-order
// arithmetic, the cost at a target error (compare), and the stability classification.
#include "sphmol/cases/shock_tube/shock_tube_settings.hpp"
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "sphmol/studies/converge.hpp"
#include "sphmol/studies/fastest_at_error.hpp"
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
  // A doubled, leading or trailing comma, and an integrator twice (the same table), are errors.
  for (const char* bad : {"leapfrog,,cvode_adams", ",leapfrog", "leapfrog,"})
    CHECK_THROWS_WITH(parse_integrator_list(bad, ""), Catch::Contains("an empty entry"));
  CHECK_THROWS_WITH(parse_integrator_list("leapfrog,leapfrog", ""), Catch::Contains("listed twice"));
  CHECK_THROWS_WITH(parse_integrator_list("arkode_erk,arkode_erk:ARKODE_HEUN_EULER_2_1_2", "ARKODE_HEUN_EULER_2_1_2"),
                    Catch::Contains("listed twice"));
  CHECK(parse_integrator_list("arkode_erk,arkode_erk:ARKODE_VERNER_8_5_6", "ARKODE_HEUN_EULER_2_1_2").size() == 2u);
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
  // Settling onto a biased level (the first tenth, the start-up, is skipped): stable.
  CHECK(classify_run(summary({0.3, 0.05, 0.02, 0.015, 0.014, 0.014, 0.014, 0.014, 0.014, 0.014}), 0.002).label == "stable");
  // Swinging about a biased level (0.01 +- 0.005): oscillating, even though e_signed never changes sign.
  const auto o = classify_run(summary({0.3, 0.015, 0.005, 0.015, 0.005, 0.015, 0.005, 0.015, 0.005, 0.015}), 0.002);
  CHECK(o.label == "oscillating");
  CHECK(o.sign_changes == 8);
  CHECK(o.amplitude == Approx(0.005));
  CHECK(classify_run(summary({0.3, 0.011, 0.009, 0.011, 0.009, 0.011, 0.009, 0.011, 0.009, 0.011}), 0.002).label == "stable");  // small wiggles ignored
  CHECK(classify_run(summary({}, "blown_up"), 0.002).label == "blown_up");
  CHECK(classify_run(summary({0.1, -3.0, 40.0, -200.0}), 0.002).label == "blown_up");  // unbounded growth
  // A case without e_signed: not called stable, only not blown up.
  nlohmann::json plain{{"status", "completed"}, {"errors", nlohmann::json::array({{{"L_inf", 0.3}}, {{"L_inf", 0.2}}})}};
  CHECK(classify_run(plain, 0.002).label == "not_blown_up");
}

TEST_CASE("cost at a target error: log-log interpolation on the error-vs-cost curve", "[studies]") {
  // error = 1 / cost^2 through (1, 1), (10, 1e-2), (100, 1e-4): exact on a log-log line.
  const std::vector<CurvePoint> c{{1.0, 1.0}, {10.0, 1e-2}, {100.0, 1e-4}};
  auto r = cost_at_error(c, 1e-1);
  REQUIRE(r);
  CHECK(r->cost == Approx(std::sqrt(10.0)));
  CHECK_FALSE(r->bound);
  CHECK(r->below == 1);
  r = cost_at_error(c, 1e-3);
  REQUIRE(r);
  CHECK(r->cost == Approx(std::sqrt(1000.0)));
  CHECK(r->below == 2);
  CHECK(cost_at_error(c, 1e-2)->cost == Approx(10.0));  // a run exactly at the target
  // Already below at the cheapest run: its cost, flagged as an upper bound.
  r = cost_at_error(c, 2.0);
  REQUIRE(r);
  CHECK(r->cost == 1.0);
  CHECK(r->bound);
  // Never reached (an error floor), and failed runs skipped.
  CHECK_FALSE(cost_at_error(c, 1e-5));
  const double inf = std::numeric_limits<double>::infinity();
  r = cost_at_error({{0.5, inf}, {1.0, 1.0}, {10.0, 1e-2}}, 1e-1);
  REQUIRE(r);
  CHECK(r->cost == Approx(std::sqrt(10.0)));
  // The first crossing counts, even if a later (noisier) run rises above the target again.
  r = cost_at_error({{1.0, 1.0}, {10.0, 1e-2}, {20.0, 0.5}, {40.0, 1e-3}}, 1e-1);
  REQUIRE(r);
  CHECK(r->below == 1);
}

TEST_CASE("stability classification of sampled start-up signals", "[studies]") {
  // e_signed(t) sampled at 20 equally spaced times over t_end = 1 s, like run_stability does.
  auto sampled = [](auto f) {
    nlohmann::json j{{"status", "completed"}, {"errors", nlohmann::json::array()}};
    for (int k = 1; k <= 20; ++k) j["errors"].push_back({{"e_signed", f(k / 20.0)}});
    return j;
  };
  const double pi = std::acos(-1.0);
  // Start-up lag that decays onto the steady profile: stable.
  CHECK(classify_run(sampled([](double t) { return -0.5 * std::exp(-t / 0.1); }), 0.01).label == "stable");
  // The same start-up, then a sustained symmetric swing of 5 % about the steady profile (period 0.3 s):
  // oscillating.
  const auto osc = classify_run(sampled([&](double t) { return -0.5 * std::exp(-t / 0.1) + 0.05 * std::sin(2 * pi * t / 0.3); }), 0.01);
  CHECK(osc.label == "oscillating");
  CHECK(osc.sign_changes >= 4);
  // A swing below the threshold is not counted.
  CHECK(classify_run(sampled([&](double t) { return 0.005 * std::sin(2 * pi * t / 0.3); }), 0.01).label == "stable");
  // A swing that grows past the velocity scale: blown up.
  CHECK(classify_run(sampled([&](double t) { return 0.01 * std::exp(6 * t) * std::sin(2 * pi * t / 0.3); }), 0.01).label == "blown_up");
  // Like the measured Poiseuille oscillation (README): e_signed 0.009 +- 0.004 with a period of 8 s,
  // 40 samples over 20 s, default threshold 0.002 v0.
  nlohmann::json j{{"status", "completed"}, {"errors", nlohmann::json::array()}};
  for (int k = 1; k <= 40; ++k) j["errors"].push_back({{"e_signed", 0.009 + 0.004 * std::cos(2 * pi * (k * 0.5) / 8.0)}});
  CHECK(classify_run(j, 0.002).label == "oscillating");
}

TEST_CASE("stability: the sound speed factor scales c, for an ideal gas through the pressures", "[studies]") {
  Config c;
  c.fluid.eos.type = "linear_relative";
  c.fluid.eos.sound_speed = 5e-3;
  CHECK(scale_sound_speed(c, 4.0) == Approx(2e-2));
  Config g;
  g.fluid.eos.type = "ideal_gas";
  g.fluid.eos.gamma = 1.4;
  g.case_name = "shock_tube";
  auto st = std::make_shared<ShockTubeSettings>();
  st->left = {1.0, 1.0, 0.0};
  st->right = {0.25, 0.1795, 0.0};
  g.case_settings = st;
  const double c0 = std::sqrt(1.4);
  CHECK(scale_sound_speed(g, 2.0) == Approx(2.0 * c0));
  const auto& s = g.settings<ShockTubeSettings>();
  CHECK(s.left.pressure == Approx(4.0));
  CHECK(s.right.pressure == Approx(4.0 * 0.1795));
  CHECK(s.right.density == 0.25);
  CHECK(st->left.pressure == 1.0);  // the scaled states are a copy: the base config is unchanged  // densities unchanged: every state's c doubles
}
