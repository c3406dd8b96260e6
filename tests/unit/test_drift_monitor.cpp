// The hydrostatic case's drift monitor (analysis/drift_monitor.hpp): the largest displacement of
// any fluid particle from its initial position over the evaluations it watches, with the minimum
// image in periodic directions; each row against its particle's start by serial index, whether the
// workspace is reordered (Workspace::order) or is a rank's local rows (WatchedRows).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

#include "sphmol/analysis/drift_monitor.hpp"
#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"

using namespace sphmol;

namespace {

constexpr std::size_t kFluid = 400, kWalls = 50;

struct Scene {
  Domain<2> domain;
  Particles<2> initial;
  std::array<std::vector<double>, 2> moved;  // fluid positions at a later evaluation, serial order
  double expected = 0.0;                     // the largest displacement, minimum image in x
};

// A box periodic in x, fluid particles that move by up to 0.2 (some across the periodic edge) and
// walls after them.
Scene scene() {
  Scene s;
  s.domain.lo = {0.0, 0.0};
  s.domain.hi = {2.0, 1.0};
  s.domain.periodic = {true, false};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ux(0.0, 2.0), uy(0.1, 0.9), step(-0.2, 0.2);
  s.initial.n_fluid = kFluid;
  for (std::size_t i = 0; i < kFluid + kWalls; ++i) {
    s.initial.x[0].push_back(ux(rng));
    s.initial.x[1].push_back(i < kFluid ? uy(rng) : -0.05);
  }
  for (std::size_t i = 0; i < kFluid; ++i) {
    double x = s.initial.x[0][i] + step(rng);
    x -= 2.0 * std::floor(x / 2.0);  // wrapped into the box, as the RHS sees it
    const double y = s.initial.x[1][i] + step(rng);
    s.moved[0].push_back(x);
    s.moved[1].push_back(y);
    const double dx = s.domain.min_image(0, x - s.initial.x[0][i]), dy = y - s.initial.x[1][i];
    s.expected = std::max(s.expected, std::hypot(dx, dy));
  }
  return s;
}

// The monitor's result after one evaluation of the workspace rows `x` (fluid first).
double drift(const Scene& s, const std::array<std::vector<double>, 2>& x, std::size_t n_fluid, const std::uint32_t* order,
             const WatchedRows& rows) {
  auto max = std::make_shared<double>(0.0);
  DriftMonitor<2> monitor(s.initial, max);
  const auto term = monitor.watch(rows);
  Workspace<2> w;
  w.n = x[0].size();
  w.n_fluid = n_fluid;
  w.domain = &s.domain;
  w.order = order;
  w.x = x;
  term->apply(w);
  return *max;
}

}  // namespace

TEST_CASE("drift monitor: the largest displacement from the start, minimum image in a periodic direction", "[analysis]") {
  const Scene s = scene();
  std::array<std::vector<double>, 2> x = s.moved;
  for (int d = 0; d < 2; ++d) x[d].insert(x[d].end(), s.initial.x[d].begin() + kFluid, s.initial.x[d].end());
  REQUIRE(s.expected > 0.2);  // diagonal steps
  CHECK(drift(s, x, kFluid, nullptr, WatchedRows{}) == s.expected);
}

TEST_CASE("drift monitor: a reordered workspace compares each row with its particle's start", "[analysis]") {
  // discretization.reorder: the workspace holds the particles in another order, Workspace::order
  // naming each row's particle.
  const Scene s = scene();
  std::vector<std::uint32_t> order(kFluid);
  for (std::size_t i = 0; i < kFluid; ++i) order[i] = static_cast<std::uint32_t>(i);
  std::shuffle(order.begin(), order.end(), std::mt19937(9));
  std::array<std::vector<double>, 2> x;
  for (int d = 0; d < 2; ++d)
    for (std::size_t i = 0; i < kFluid; ++i) x[d].push_back(s.moved[d][order[i]]);
  CHECK(drift(s, x, kFluid, order.data(), WatchedRows{}) == s.expected);
}

TEST_CASE("drift monitor: a rank's rows, its own only, by serial index", "[analysis]") {
  // A rank's local system: its own particles and halo copies of others' in some order; the halo
  // rows are its neighbours' to watch, even when they have moved farther.
  const Scene s = scene();
  WatchedRows rows;
  std::array<std::vector<double>, 2> x;
  double mine = 0.0;
  for (std::size_t k = kFluid; k-- > 0;) {  // the rows in reverse serial order
    const bool own = k % 3 != 0;
    rows.id.push_back(k);
    rows.owned.push_back(own ? 1 : 0);
    for (int d = 0; d < 2; ++d) {
      x[d].push_back(s.moved[d][k]);
      rows.start.push_back(s.initial.x[d][k]);
    }
    if (own) {
      const double dx = s.domain.min_image(0, s.moved[0][k] - s.initial.x[0][k]), dy = s.moved[1][k] - s.initial.x[1][k];
      mine = std::max(mine, std::hypot(dx, dy));
    }
  }
  // A halo copy far from its start: not this rank's to count.
  x[1][0] += 10.0;
  REQUIRE(rows.owned[0] == 0);
  CHECK(drift(s, x, kFluid, nullptr, rows) == mine);

  SECTION("the rows' starts, not the whole scene's, once the rank has dropped the scene") {
    auto max = std::make_shared<double>(0.0);
    DriftMonitor<2> monitor(s.initial, max);
    REQUIRE(monitor.starts_held() == 2 * kFluid);
    const auto whole = monitor.watch(WatchedRows{});
    monitor.release_whole();
    CHECK(monitor.starts_held() == 0);
    const auto term = monitor.watch(rows);
    Workspace<2> w;
    w.n = w.n_fluid = kFluid;
    w.domain = &s.domain;
    w.x = x;
    term->apply(w);
    CHECK(*max == mine);
  }
  SECTION("a local system's rows without their starts are refused") {
    WatchedRows bare = rows;
    bare.start.clear();
    DriftMonitor<2> monitor(s.initial, std::make_shared<double>(0.0));
    CHECK_THROWS_AS(monitor.watch(bare), std::invalid_argument);
  }
}
