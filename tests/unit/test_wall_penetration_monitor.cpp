// The dam break's wall penetration monitor (analysis/wall_penetration_monitor.hpp): the particles
// that passed a wall, counted once each over evaluations, and the smallest gap to a wall surface,
// the same as a plain count and minimum for any thread count.
#include <catch2/catch.hpp>

#include <omp.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "sphmol/analysis/wall_penetration_monitor.hpp"

using namespace sphmol;

TEST_CASE("wall penetration monitor: count and gap equal a serial count and minimum on 1, 2 and 3 threads", "[analysis][threads]") {
  const double Lx = 4.0, Ly = 3.0;
  const std::size_t n = 1237;
  // Three evaluations of random positions over a box a little larger than the tank: particles pass
  // the floor, the side walls below their top, or fly over them (not a penetration), some again.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ux(-0.3, Lx + 0.3), uy(-0.3, Ly + 0.5);
  std::vector<std::array<std::vector<double>, 2>> evals(3);
  for (auto& e : evals)
    for (std::size_t i = 0; i < n; ++i) {
      e[0].push_back(ux(rng));
      e[1].push_back(uy(rng));
    }
  // The reference, one particle after the other.
  std::vector<std::uint8_t> crossed(n, 0);
  long count = 0;
  double gap = std::numeric_limits<double>::infinity();
  for (const auto& e : evals)
    for (std::size_t i = 0; i < n; ++i) {
      const double x = e[0][i], y = e[1][i];
      const bool out = y < 0.0 || (y < Ly && (x < 0.0 || x > Lx));
      if (out && !crossed[i]) {
        crossed[i] = 1;
        ++count;
      }
      if (!out && x >= 0.0 && x <= Lx) gap = std::min({gap, x, Lx - x, y});
    }
  REQUIRE(count > 50);
  REQUIRE(count < static_cast<long>(n) / 2);
  for (const int threads : {1, 2, 3}) {
    INFO("threads " << threads);
    auto state = std::make_shared<WallPenetration>();
    const WallPenetrationMonitor monitor(Lx, Ly, state);
    Workspace<2> w;
    w.n = w.n_fluid = n;
    for (const auto& e : evals) {
      w.x = e;
#pragma omp parallel num_threads(threads)
      monitor.apply(w);
    }
    CHECK(state->count == count);
    CHECK(state->min_gap == gap);
    CHECK(state->crossed == crossed);
  }
}
