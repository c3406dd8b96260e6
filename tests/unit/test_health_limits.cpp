// The physical bounds of the per-step health check (run/health_limits.hpp, run/health_check.hpp):
// derived from the scene, and each one ends a state that crosses it with a named BlowUp.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/run/case_registry.hpp"
#include "sphmol/run/health_check.hpp"
#include "sphmol/run/health_limits.hpp"

using namespace sphmol;

namespace {

Config shipped(const std::string& name, const std::vector<std::string>& set = {}) {
  return load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/" + name + ".yaml", set);
}

// The cause of the BlowUp the check throws for state y, or "" when the state passes.
std::string cause_of(HealthCheck<2>& check, const std::vector<double>& y) {
  try {
    check(1e-3, y.data(), 1e-3);
  } catch (const BlowUp& b) {
    return b.cause;
  }
  return "";
}

}  // namespace

TEST_CASE("health limits: velocity scales come from the scene", "[health]") {
  CHECK(scene_velocity_scale(shipped("couette")) == 2.5e-5);
  // Poiseuille centre-line speed F l^2 / (8 nu) = 2e-4 * 1e-6 / 8e-6.
  CHECK(scene_velocity_scale(shipped("poiseuille")) == Approx(2.5e-5));
  CHECK(scene_velocity_scale(shipped("taylor_green")) == 1.0);
  CHECK(scene_velocity_scale(shipped("cavity")) == 1.0);
  CHECK(scene_velocity_scale(shipped("hydrostatic")) == Approx(std::sqrt(2 * 9.81 * 0.9)));
  CHECK(scene_velocity_scale(shipped("dam_break")) == Approx(std::sqrt(2 * 9.81 * 2.0)));
  CHECK(scene_velocity_scale(shipped("shock_tube")) == 0.0);
}

TEST_CASE("health check: kinetic energy gain, speed and density bounds end the run with a named cause", "[health]") {
  const Config c = shipped("taylor_green", {"discretization.particles_across=16"});
  auto cs = case_registry().at("taylor_green").d2();
  auto sys = cs->build(c);
  std::vector<double> y0 = sys->initial_state(), ydot(y0.size());
  sys->rhs(0.0, y0.data(), ydot.data());
  const HealthLimits lim = health_limits<2>(c, *sys, y0.data());
  CHECK(lim.max_speed == 10.0);  // 10 U = c = 10 m/s: the sound speed
  CHECK(lim.max_compression == Approx(0.2));
  CHECK(lim.max_expansion == Approx(0.2));  // no free surface
  HealthCheck<2> check(*sys, y0.data(), 0.0, lim);
  const auto& L = sys->layout();

  CHECK(cause_of(check, y0) == "");
  // Every velocity x 1.1: 21 % more kinetic energy than the initial state had, and no input.
  std::vector<double> y = y0;
  for (int d = 0; d < 2; ++d)
    for (std::size_t i = 0; i < L.n; ++i) y[L.velocity(d) + i] *= 1.1;
  CHECK(cause_of(check, y).rfind("kinetic energy ", 0) == 0);
  // 5 % more stays inside the 10 % slack.
  y = y0;
  for (int d = 0; d < 2; ++d)
    for (std::size_t i = 0; i < L.n; ++i) y[L.velocity(d) + i] *= std::sqrt(1.05);
  CHECK(cause_of(check, y) == "");
  // One particle at Mach 1.5.
  y = y0;
  y[L.velocity(0) + 7] = 15.0;
  y[L.velocity(1) + 7] = 0.0;
  const std::string speed = cause_of(check, y);
  CHECK(speed.rfind("speed 15 m/s above 10 m/s, the sound speed c = 10 m/s", 0) == 0);

  // Densities are those of the latest RHS evaluation: compress the lattice by 20 % in x.
  y = y0;
  for (std::size_t i = 0; i < L.n; ++i) y[L.position(0) + i] *= 0.75;
  sys->rhs(0.0, y.data(), ydot.data());
  const std::string rho = cause_of(check, y);
  INFO(rho);
  CHECK(rho.rfind("density ratio rho/rho0 = ", 0) == 0);
}

TEST_CASE("health limits: free surfaces bound compression only; ideal gases have no speed or density bound", "[health]") {
  {
    const Config c = shipped("hydrostatic", {"discretization.particles_across=10"});
    auto cs = case_registry().at("hydrostatic").d2();
    auto sys = cs->build(c);
    const auto y0 = sys->initial_state();
    const HealthLimits lim = health_limits<2>(c, *sys, y0.data());
    CHECK(std::isinf(lim.max_expansion));
    CHECK(lim.max_compression == Approx(std::max(0.2, 10 * 2 * 9.81 * 0.9 / (29.7 * 29.7))));
    CHECK(lim.max_speed == 29.7);  // 10 sqrt(2 g H) = 42 m/s is above c
    CHECK(lim.g[1] == -9.81);
  }
  {
    const Config c = shipped("shock_tube_1d");
    auto cs = case_registry().at("shock_tube").d1();
    auto sys = cs->build(c);
    const auto y0 = sys->initial_state();
    const HealthLimits lim = health_limits<1>(c, *sys, y0.data());
    CHECK(std::isinf(lim.max_speed));
    CHECK(lim.rho0 == 0.0);
    CHECK(lim.energy_budget > 0.0);  // the internal energy
  }
}
