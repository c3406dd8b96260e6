// Outflow (run/outflow.hpp): a fluid particle outside the domain along an open axis is taken out of
// the run. Its rates are zero from then on (the body force included), its former neighbours no
// longer feel it, with every neighbour search, and the health check notes the exit instead of
// ending the run.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/run/health_check.hpp"
#include "sphmol/run/health_limits.hpp"
#include "sphmol/run/outflow.hpp"
#include "sphmol/time/blow_up.hpp"
#include "shot_scene.hpp"

using namespace sphmol;

namespace {

// The shot scene (tests/shot_scene.hpp) under gravity.
Config shot_scene(std::vector<std::string> set = {}) {
  set.insert(set.begin(), "fluid.body_force=[0.0, -9.81]");
  return sphmol::testing::shot_scene(set);
}

std::size_t bullet_of(const SphSystem<2>& sys, const std::vector<double>& y) {
  const auto& L = sys.layout();
  for (std::size_t i = 0; i < L.n; ++i)
    if (std::abs(y[L.position(0) + i] - 0.31) < 1e-9 && std::abs(y[L.position(1) + i] - 0.19) < 1e-9) return i;
  FAIL("no fluid particle at (0.31, 0.19)");
  return 0;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("outflow: a particle taken out has zero rates and its neighbours no longer feel it", "[outflow][health]") {
  for (const std::string search : {"kdtree", "cell_list", "all_pairs"}) {
    DYNAMIC_SECTION(search) {
      const Config c = shot_scene({"discretization.neighbor_search=" + search});
      auto cs = make_case<2>(c);
      auto sys = cs->build(c);
      const auto& L = sys->layout();
      std::vector<double> y = sys->initial_state();
      const std::size_t p = bullet_of(*sys, y);
      const std::size_t blocks = L.size() / L.n;
      REQUIRE(L.has_density);
      // Just past the open face, within the kernel support of the block's right column (x = 0.29).
      REQUIRE(sys->domain().hi[0] == Approx(0.34));
      const double x_out = 0.345;
      y[L.position(0) + p] = x_out;
      REQUIRE(x_out - 0.29 < 2.0 * sys->smoothing_length());

      // Reference: the same particle far away, where no pair reaches it.
      std::vector<double> far = y, f_far(y.size()), f_in(y.size()), f_out(y.size());
      far[L.position(0) + p] = 5.0;
      sys->rhs(0.0, far.data(), f_far.data());
      // Not taken out: its neighbours feel it (the test would pass vacuously otherwise).
      sys->rhs(0.0, y.data(), f_in.data());
      bool felt = false;
      for (std::size_t b = 0; b < blocks; ++b)
        for (std::size_t i = 0; i < L.n; ++i)
          if (i != p && !same_bits(f_in[b * L.n + i], f_far[b * L.n + i])) felt = true;
      CHECK(felt);

      // The health check notes the exit and passes the state.
      const HealthLimits lim = health_limits<2>(c, cs->velocity_scale(c), cs->free_surface(), *sys, y.data());
      HealthCheck<2> check(*sys, y.data(), 0.0, lim);
      CHECK_NOTHROW(check(1e-3, y.data(), 1e-3));
      CHECK(check.exits());

      Outflow<2> outflow(*sys, 0.05);
      REQUIRE(outflow.take_out(*sys, y.data(), 1e-3));
      CHECK(sys->is_retired(p));
      CHECK(sys->retired() == std::vector<std::size_t>{p});
      CHECK(outflow.count() == 1);
      const double m = sys->particles().mass[p];
      double M = 0.0;
      for (std::size_t i = 0; i < L.n; ++i) M += sys->particles().mass[i];
      CHECK(outflow.fraction() == Approx(m / M));
      const auto j = outflow.to_json();
      CHECK(j["particles"] == 1);
      CHECK(j["t_first"] == 1e-3);
      CHECK(j["mass"].get<double>() == m);
      CHECK_FALSE(outflow.warning().empty());
      // Its velocity is zero, it stays where it left, and it is not taken out twice.
      for (int d = 0; d < 2; ++d) CHECK(y[L.velocity(d) + p] == 0.0);
      CHECK(y[L.position(0) + p] == x_out);
      CHECK_FALSE(outflow.take_out(*sys, y.data(), 2e-3));
      CHECK(outflow.count() == 1);

      sys->rhs(1e-3, y.data(), f_out.data());
      // Every rate of it is zero, the body force's included.
      for (std::size_t b = 0; b < blocks; ++b) CHECK(f_out[b * L.n + p] == 0.0);
      // Every other particle's rates are those without it, bit for bit.
      std::size_t differ = 0;
      for (std::size_t b = 0; b < blocks; ++b)
        for (std::size_t i = 0; i < L.n; ++i)
          if (i != p && !same_bits(f_out[b * L.n + i], f_far[b * L.n + i])) ++differ;
      CHECK(differ == 0);
      // The check passes it from now on: no new exit.
      CHECK_NOTHROW(check(2e-3, y.data(), 1e-3));
      CHECK_FALSE(check.exits());
    }
  }
}

TEST_CASE("outflow: with a reordered workspace the particle taken out is the one in the state", "[outflow][reorder]") {
  // Reordering (neighbors/particle_reorder.hpp) moves the particle within the workspace: its kind
  // and its rates follow it there. The summation order differs from the unordered run by round-off.
  const Config c = shot_scene({"discretization.reorder=true"});
  auto cs = make_case<2>(c);
  auto sys = cs->build(c);
  REQUIRE(sys->reorder());
  const auto& L = sys->layout();
  std::vector<double> y = sys->initial_state();
  const std::size_t p = bullet_of(*sys, y);
  const std::size_t blocks = L.size() / L.n;
  y[L.position(0) + p] = 0.345;
  std::vector<double> far = y, f_far(y.size()), f_out(y.size());
  far[L.position(0) + p] = 5.0;
  sys->rhs(0.0, far.data(), f_far.data());
  Outflow<2> outflow(*sys, 0.05);
  REQUIRE(outflow.take_out(*sys, y.data(), 1e-3));
  sys->rhs(1e-3, y.data(), f_out.data());
  const auto& order = sys->workspace_order();
  bool moved = false;
  for (std::size_t k = 0; k < order.size(); ++k) moved = moved || order[k] != k;
  REQUIRE(moved);  // the workspace order is not the state's
  for (std::size_t b = 0; b < blocks; ++b) CHECK(f_out[b * L.n + p] == 0.0);
  double worst = 0.0, scale = 0.0;
  for (std::size_t b = 0; b < blocks; ++b)
    for (std::size_t i = 0; i < L.n; ++i)
      if (i != p) {
        worst = std::max(worst, std::abs(f_out[b * L.n + i] - f_far[b * L.n + i]));
        scale = std::max(scale, std::abs(f_far[b * L.n + i]));
      }
  CHECK(worst <= 1e-12 * scale);
}

TEST_CASE("outflow: more than the allowed fraction of the fluid mass is a blow-up", "[outflow][health]") {
  const Config c = shot_scene();
  auto cs = make_case<2>(c);
  auto sys = cs->build(c);
  const auto& L = sys->layout();
  std::vector<double> y = sys->initial_state();
  const std::size_t p = bullet_of(*sys, y);
  y[L.position(0) + p] = 0.36;
  // One particle of 101 is about 1 % of the mass.
  Outflow<2> outflow(*sys, 0.005);
  try {
    outflow.take_out(*sys, y.data(), 0.01);
    FAIL("no BlowUp");
  } catch (const BlowUp& b) {
    CHECK(b.particle == static_cast<long>(p));
    CHECK(std::string(b.cause).rfind("outflow: 1 fluid particle(s), 0.009901 of the fluid mass, left the domain", 0) == 0);
    CHECK_THAT(std::string(b.cause), Catch::Matchers::Contains("health.max_outflow_fraction = 0.005"));
  }
}

TEST_CASE("outflow: fluid outside the domain along a periodic axis, or inside it, stays", "[outflow]") {
  const Config c = shot_scene({"scene.domain.boundaries=[periodic, open]", "scene.domain.lo=[0.0, 0.0]",
                               "scene.domain.hi=[0.4, 0.4]"});
  auto cs = make_case<2>(c);
  auto sys = cs->build(c);
  const auto& L = sys->layout();
  std::vector<double> y = sys->initial_state();
  y[L.position(0)] = 0.45;  // past the periodic face: wrapped, not out
  CHECK(fluid_outside_domain(*sys, y.data()).empty());
  y[L.position(1)] = sys->domain().hi[1] + 0.01;  // past the open face
  CHECK(fluid_outside_domain(*sys, y.data()) == std::vector<std::size_t>{0});
}

TEST_CASE("outflow: fluid beyond a face closed to outflow (a wall) ends the run as blown up", "[outflow][health]") {
  // The shot scene with walls along x, the top left open: the right face is a wall, the top an
  // outflow face (Domain::outflow).
  const Config c = shot_scene({"scene.domain.boundaries=[wall, wall]", "scene.domain.open_faces=[y_hi]"});
  auto cs = make_case<2>(c);
  auto sys = cs->build(c);
  const auto& dom = sys->domain();
  REQUIRE_FALSE(dom.outflow[0][0]);
  REQUIRE_FALSE(dom.outflow[0][1]);
  REQUIRE_FALSE(dom.outflow[1][0]);
  REQUIRE(dom.outflow[1][1]);
  const auto& L = sys->layout();
  std::vector<double> y0 = sys->initial_state();
  const std::size_t p = bullet_of(*sys, y0);
  const HealthLimits lim = health_limits<2>(c, cs->velocity_scale(c), cs->free_surface(), *sys, y0.data());

  // Through the top: noted, taken out by the run.
  std::vector<double> y = y0;
  y[L.position(1) + p] = dom.hi[1] + 0.005;
  HealthCheck<2> top(*sys, y0.data(), 0.0, lim);
  CHECK_NOTHROW(top(1e-3, y.data(), 1e-3));
  CHECK(top.exits());
  CHECK(fluid_outside_domain(*sys, y.data()) == std::vector<std::size_t>{p});

  // Through the right wall: a blow-up that says so.
  y = y0;
  y[L.position(0) + p] = dom.hi[0] + 0.005;
  HealthCheck<2> side(*sys, y0.data(), 0.0, lim);
  try {
    side(1e-3, y.data(), 1e-3);
    FAIL("no BlowUp");
  } catch (const BlowUp& b) {
    CHECK(b.particle == static_cast<long>(p));
    CHECK_THAT(std::string(b.cause), Catch::Matchers::Contains("left the domain in direction 0 through a face closed to outflow"));
  }
}
