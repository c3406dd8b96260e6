// The dam break's wall penetration monitor (analysis/wall_penetration_monitor.hpp): the particles
// that passed a wall, counted once each over evaluations, and the smallest gap to a wall surface,
// the same as a plain count and minimum for any thread count; a rank's rows (rhs/monitor.hpp) by
// serial index, its own only, and combined with another rank's results.
#include <catch2/catch.hpp>

#include <omp.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <vector>

#include "sphmol/analysis/wall_penetration_monitor.hpp"

using namespace sphmol;

namespace {

using Evaluations = std::vector<std::array<std::vector<double>, 2>>;

// A monitor of the tank watching `rows`, after the evaluations of `evals` (positions of the rows) on
// `threads` threads; its results in `state`.
std::unique_ptr<WallPenetrationMonitor> watched(double Lx, double Ly, const WatchedRows& rows, std::size_t n_rows,
                                                const Evaluations& evals, int threads, std::shared_ptr<WallPenetration> state) {
  auto monitor = std::make_unique<WallPenetrationMonitor>(Lx, Ly, std::move(state));
  const auto term = monitor->watch(rows);
  Workspace<2> w;
  w.n = w.n_fluid = n_rows;
  for (const auto& e : evals) {
    w.x = e;
#pragma omp parallel num_threads(threads)
    term->apply(w);
  }
  return monitor;
}

// The monitor's set of crossed particles as a flag per particle of a scene of n.
std::vector<std::uint8_t> flags(const std::set<std::uint64_t>& crossed, std::size_t n) {
  std::vector<std::uint8_t> f(n, 0);
  for (const std::uint64_t k : crossed) f.at(k) = 1;
  return f;
}

}  // namespace

TEST_CASE("wall penetration monitor: count and gap equal a serial count and minimum on 1, 2 and 3 threads", "[analysis][threads]") {
  const double Lx = 4.0, Ly = 3.0;
  const std::size_t n = 1237;
  // Three evaluations of random positions over a box a little larger than the tank: particles pass
  // the floor, the side walls below their top, or fly over them (not a penetration), some again.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ux(-0.3, Lx + 0.3), uy(-0.3, Ly + 0.5);
  Evaluations evals(3);
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
    const auto monitor = watched(Lx, Ly, WatchedRows{}, n, evals, threads, state);
    CHECK(state->count == count);
    CHECK(state->min_gap == gap);
    CHECK(flags(state->crossed, n) == crossed);
  }
}

namespace {

// Another rank's results, as combine() would receive them: its flagged particles and its smallest gap.
class OneOtherRank final : public RankReduction {
 public:
  OneOtherRank(std::vector<std::uint64_t> flagged, double gap) : flagged_(std::move(flagged)), gap_(gap) {}
  double min(double v) const override { return std::min(v, gap_); }
  double max(double v) const override { return std::max(v, gap_); }
  std::vector<std::uint64_t> all_gather(const std::vector<std::uint64_t>& mine) const override {
    std::vector<std::uint64_t> all = mine;
    all.insert(all.end(), flagged_.begin(), flagged_.end());
    return all;
  }

 private:
  std::vector<std::uint64_t> flagged_;
  double gap_;
};

}  // namespace

TEST_CASE("wall penetration monitor: a rank's rows watch its own particles by serial index, combined with the other ranks'",
          "[analysis][threads][monitors]") {
  const double Lx = 4.0, Ly = 3.0;
  const std::size_t n = 1500;  // the scene's fluid particles
  // A rank's local system: 700 rows in ascending serial index, every third one a halo copy (not owned).
  std::mt19937 rng(5);
  std::vector<std::uint64_t> all(n);
  for (std::size_t k = 0; k < n; ++k) all[k] = k;
  std::shuffle(all.begin(), all.end(), rng);
  WatchedRows rows;
  rows.id.assign(all.begin(), all.begin() + 700);
  std::sort(rows.id.begin(), rows.id.end());
  for (std::size_t i = 0; i < rows.id.size(); ++i) rows.owned.push_back(i % 3 == 2 ? 0 : 1);
  std::uniform_real_distribution<double> ux(-0.3, Lx + 0.3), uy(-0.3, Ly + 0.5);
  Evaluations evals(3);
  for (auto& e : evals)
    for (std::size_t i = 0; i < rows.id.size(); ++i) {
      e[0].push_back(ux(rng));
      e[1].push_back(uy(rng));
    }
  // The reference: the owned rows only, flagged by serial index.
  std::vector<std::uint8_t> crossed(n, 0);
  double gap = std::numeric_limits<double>::infinity();
  for (const auto& e : evals)
    for (std::size_t i = 0; i < rows.id.size(); ++i) {
      if (!rows.owned[i]) continue;
      const double x = e[0][i], y = e[1][i];
      if (y < 0.0 || (y < Ly && (x < 0.0 || x > Lx))) crossed[rows.id[i]] = 1;
      else if (x >= 0.0 && x <= Lx) gap = std::min({gap, x, Lx - x, y});
    }
  // The other rank flagged two particles, one of which this rank flagged too, and came nearer a wall.
  std::vector<std::uint64_t> theirs;
  for (std::size_t k = 0; k < n && theirs.size() < 1; ++k)
    if (crossed[k]) theirs.push_back(k);
  for (std::size_t k = 0; k < n && theirs.size() < 2; ++k)
    if (!crossed[k]) theirs.push_back(k);
  REQUIRE(theirs.size() == 2);
  const long own_count = std::count(crossed.begin(), crossed.end(), std::uint8_t{1});
  REQUIRE(own_count > 30);
  for (const int threads : {1, 2, 3}) {
    INFO("threads " << threads);
    auto state = std::make_shared<WallPenetration>();
    const auto monitor = watched(Lx, Ly, rows, rows.id.size(), evals, threads, state);
    CHECK(flags(state->crossed, n) == crossed);
    CHECK(state->count == own_count);
    CHECK(state->min_gap == gap);
    monitor->combine(OneOtherRank(theirs, gap / 2));
    CHECK(state->count == own_count + 1);
    CHECK(state->crossed.count(theirs[1]) == 1);
    CHECK(state->min_gap == gap / 2);
  }
}

TEST_CASE("wall penetration monitor: a reordered workspace flags particles by their serial index", "[analysis]") {
  // With discretization.reorder the workspace holds the particles in Morton order (Workspace::order:
  // workspace index -> serial index); the flags must name the particles, not their workspace rows.
  const double Lx = 4.0, Ly = 3.0;
  const std::size_t n = 500;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ux(-0.3, Lx + 0.3), uy(-0.3, Ly + 0.5);
  std::array<std::vector<double>, 2> serial;
  for (std::size_t i = 0; i < n; ++i) {
    serial[0].push_back(ux(rng));
    serial[1].push_back(uy(rng));
  }
  std::vector<std::uint8_t> crossed(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = serial[0][i], y = serial[1][i];
    crossed[i] = (y < 0.0 || (y < Ly && (x < 0.0 || x > Lx))) ? 1 : 0;
  }
  REQUIRE(std::count(crossed.begin(), crossed.end(), std::uint8_t{1}) > 20);
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
  std::shuffle(order.begin(), order.end(), rng);
  Workspace<2> w;
  w.n = w.n_fluid = n;
  w.order = order.data();
  for (int d = 0; d < 2; ++d) {
    w.x[d].resize(n);
    for (std::size_t i = 0; i < n; ++i) w.x[d][i] = serial[d][order[i]];
  }
  auto state = std::make_shared<WallPenetration>();
  WallPenetrationMonitor monitor(Lx, Ly, state);
  const auto term = monitor.watch(WatchedRows{});
#pragma omp parallel num_threads(2)
  term->apply(w);
  CHECK(flags(state->crossed, n) == crossed);
  CHECK(state->count == std::count(crossed.begin(), crossed.end(), std::uint8_t{1}));
}

TEST_CASE("wall penetration monitor: holds the crossed particles only, nothing per particle of the scene", "[analysis][monitors]") {
  // Over MPI ranks every rank has the monitor for the whole run: what it keeps must not grow with
  // the scene (a sound run keeps nothing).
  auto state = std::make_shared<WallPenetration>();
  WallPenetrationMonitor monitor(4.0, 3.0, state);
  const auto term = monitor.watch(WatchedRows{});
  Workspace<2> w;
  w.n = w.n_fluid = 3;
  w.x[0] = {1.0, 2.0, -0.1};  // the third beside the left wall, below its top
  w.x[1] = {1.0, 2.0, 1.0};
#pragma omp parallel num_threads(2)
  term->apply(w);
  CHECK(state->crossed == std::set<std::uint64_t>{2});
  CHECK(state->count == 1);
  w.x[0][2] = 0.5;  // back inside: still counted once
#pragma omp parallel num_threads(2)
  term->apply(w);
  CHECK(state->count == 1);
  CHECK(state->min_gap == 0.5);
}
