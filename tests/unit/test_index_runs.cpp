// Runs of an index map (parallel/index_runs.hpp), with which the distributed evaluation copies the
// owned rows into the local system and their rates back: the runs must cover every row once, in
// order, be maximal but for the length cap, and copying by runs must give what the row-by-row
// copy gives, for maps with gaps (halo rows between the owned ones), unit gaps, a decreasing step
// and a single row.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <vector>

#include "sphmol/parallel/index_runs.hpp"

using namespace sphmol::parallel;

namespace {

// An increasing map of n rows into a larger set, as the owned rows among the halo's: gaps of
// 0 to 3 rows, more often none.
std::vector<std::uint32_t> increasing_map(std::size_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> gap(0, 9);
  std::vector<std::uint32_t> at(n);
  std::uint32_t k = static_cast<std::uint32_t>(gap(rng));
  for (std::size_t i = 0; i < n; ++i) {
    at[i] = k;
    const int g = gap(rng);
    k += 1 + static_cast<std::uint32_t>(g > 6 ? g - 6 : 0);
  }
  return at;
}

// The runs' invariants against the map itself.
void check_runs(const std::vector<std::uint32_t>& at, std::size_t cap) {
  const std::vector<IndexRun> runs = index_runs(at.data(), at.size(), cap);
  std::size_t next = 0;
  for (const IndexRun& r : runs) {
    REQUIRE(r.from == next);  // in order, no row missed or repeated
    REQUIRE(r.length >= 1);
    REQUIRE(r.length <= cap);
    for (std::size_t i = 0; i < r.length; ++i) REQUIRE(at[r.from + i] == r.to + i);
    const std::size_t e = r.from + r.length;
    // Maximal: the next row continues the run only where the cap cut it.
    if (e < at.size() && at[e] == r.to + r.length) REQUIRE(r.length == cap);
    next = e;
  }
  REQUIRE(next == at.size());
}

}  // namespace

TEST_CASE("index runs: cover the map in order, maximal up to the cap", "[halo][unit]") {
  for (std::uint32_t seed = 1; seed <= 5; ++seed) {
    const std::vector<std::uint32_t> at = increasing_map(3000, seed);
    for (const std::size_t cap : {std::size_t{1}, std::size_t{7}, std::size_t{4096}}) check_runs(at, cap);
  }
  // A lattice row split by the halo: rows 0-4 then 10-12; a step back (not increasing); one row.
  check_runs({0, 1, 2, 3, 4, 10, 11, 12}, 100);
  REQUIRE(index_runs(std::vector<std::uint32_t>{0, 1, 2, 3, 4, 10, 11, 12}.data(), 8, 100).size() == 2);
  check_runs({5, 6, 2, 3, 4}, 100);
  REQUIRE(index_runs(std::vector<std::uint32_t>{5, 6, 2, 3, 4}.data(), 5, 100).size() == 2);
  check_runs({9}, 4);
  REQUIRE(index_runs(nullptr, 0, 4).empty());
  // One unbroken run is cut at the cap: 10 rows, cap 4 -> 4 + 4 + 2.
  std::vector<std::uint32_t> straight(10);
  for (std::uint32_t i = 0; i < 10; ++i) straight[i] = 3 + i;
  const std::vector<IndexRun> cut = index_runs(straight.data(), straight.size(), 4);
  REQUIRE(cut.size() == 3);
  REQUIRE(cut[2].from == 8);
  REQUIRE(cut[2].to == 11);
  REQUIRE(cut[2].length == 2);
}

TEST_CASE("index runs: copies by runs equal the row-by-row copies", "[halo][unit]") {
  const std::vector<std::uint32_t> at = increasing_map(5000, 42);
  const std::size_t m = at.back() + 1;
  std::vector<double> dense(at.size()), wide(m);
  for (std::size_t i = 0; i < dense.size(); ++i) dense[i] = 0.5 + static_cast<double>(i);
  for (std::size_t k = 0; k < m; ++k) wide[k] = -1.0 - static_cast<double>(k);
  for (const std::size_t cap : {std::size_t{3}, std::size_t{4096}}) {
    const std::vector<IndexRun> runs = index_runs(at.data(), at.size(), cap);
    // Into the wide layout: the rows between runs keep their values.
    std::vector<double> by_runs = wide, by_rows = wide;
    for (const IndexRun& r : runs) scatter_run(r, dense.data(), by_runs.data());
    for (std::size_t i = 0; i < at.size(); ++i) by_rows[at[i]] = dense[i];
    REQUIRE(by_runs == by_rows);
    // And back.
    std::vector<double> back_runs(at.size(), 0.0), back_rows(at.size(), 0.0);
    for (const IndexRun& r : runs) gather_run(r, wide.data(), back_runs.data());
    for (std::size_t i = 0; i < at.size(); ++i) back_rows[i] = wide[at[i]];
    REQUIRE(back_runs == back_rows);
  }
}
