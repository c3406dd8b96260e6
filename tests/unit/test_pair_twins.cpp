// The twin tables of symmetric pair passes (neighbors/pair_twins.hpp): every lower entry of a fluid
// row points at the record of the same pair in the other row, records number the upper parts in row
// order, and a list that holds a pair in one direction only is reported incomplete.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "sphmol/neighbors/pair_twins.hpp"

using namespace sphmol;

namespace {

// A random symmetric list over n particles, the first nf fluid: fluid-fluid pairs both ways, and
// fluid-wall pairs listed in the fluid row and in the wall row (wall rows hold fluid neighbours only).
PairList random_list(std::size_t n, std::size_t nf, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<std::vector<std::uint32_t>> rows(n);
  std::bernoulli_distribution linked(0.3);
  for (std::size_t i = 0; i < nf; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (linked(rng)) {
        rows[i].push_back(static_cast<std::uint32_t>(j));
        rows[j].push_back(static_cast<std::uint32_t>(i));
      }
  PairList list;
  list.clear(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::sort(rows[i].begin(), rows[i].end());
    list.j.insert(list.j.end(), rows[i].begin(), rows[i].end());
    list.offset[i + 1] = static_cast<std::uint32_t>(list.j.size());
  }
  return list;
}

}  // namespace

TEST_CASE("pair twins: each lower entry finds the record of its pair in the other row", "[unit][neighbors]") {
  for (unsigned seed : {1u, 2u, 3u}) {
    const std::size_t n = 40, nf = 30;
    const PairList list = random_list(n, nf, seed);
    PairTwins t;
    t.build(list, nf);
    REQUIRE(t.complete);
    REQUIRE(t.rows() == nf);
    // Record r of row j stands for entry upper[j] + (r - record[j]) of row j.
    std::vector<std::uint32_t> record_row(t.records()), record_entry(t.records());
    std::size_t upper_entries = 0, lower_entries = 0;
    for (std::size_t j = 0; j < nf; ++j) {
      REQUIRE(t.record[j + 1] - t.record[j] == list.offset[j + 1] - t.upper[j]);
      for (std::uint32_t q = t.upper[j]; q < list.offset[j + 1]; ++q) {
        CHECK(list.j[q] > j);
        record_row[t.record[j] + (q - t.upper[j])] = static_cast<std::uint32_t>(j);
        record_entry[t.record[j] + (q - t.upper[j])] = q;
        ++upper_entries;
      }
    }
    CHECK(t.records() == upper_entries);
    for (std::size_t i = 0; i < nf; ++i)
      for (std::uint32_t q = list.offset[i]; q < t.upper[i]; ++q) {
        const std::uint32_t j = list.j[q];
        CHECK(j < i);
        const std::uint32_t r = t.twin[q];
        REQUIRE(r < t.records());
        CHECK(record_row[r] == j);                 // recorded in row j ...
        CHECK(list.j[record_entry[r]] == i);        // ... at its entry for i
        ++lower_entries;
      }
    CHECK(lower_entries > 0);
  }
}

TEST_CASE("pair twins: a pair listed in one direction only leaves the tables incomplete", "[unit][neighbors]") {
  PairList list = random_list(20, 20, 7);
  PairTwins t;
  t.build(list, 20);
  REQUIRE(t.complete);
  // Drop the first upper entry of some row: its pair stays in the other row's lower part.
  std::size_t row = 0;
  while (t.upper[row] == list.offset[row + 1]) ++row;
  list.j.erase(list.j.begin() + t.upper[row]);
  for (std::size_t i = row + 1; i < list.offset.size(); ++i) --list.offset[i];
  t.build(list, 20);
  CHECK_FALSE(t.complete);
}

TEST_CASE("pair twins: each block lists every other block its rows' lower parts reach", "[unit][neighbors]") {
  const std::size_t n = 120, nf = 100, block = 8;
  const PairList list = random_list(n, nf, 11);
  PairTwins t;
  t.build(list, nf, block);
  REQUIRE(t.n_deps.size() == (nf + block - 1) / block);
  for (std::size_t b = 0; b < t.n_deps.size(); ++b) {
    std::vector<std::uint32_t> want;
    for (std::size_t i = b * block; i < std::min(nf, (b + 1) * block); ++i)
      for (std::uint32_t q = list.offset[i]; q < t.upper[i]; ++q)
        if (list.j[q] / block != b) want.push_back(static_cast<std::uint32_t>(list.j[q] / block));
    std::sort(want.begin(), want.end());
    want.erase(std::unique(want.begin(), want.end()), want.end());
    if (want.size() > PairTwins::kMaxDeps) {
      CHECK(t.n_deps[b] == PairTwins::kNoDeps);
      continue;
    }
    REQUIRE(t.n_deps[b] == want.size());
    std::vector<std::uint32_t> got(t.deps.begin() + static_cast<long>(b * PairTwins::kMaxDeps),
                                   t.deps.begin() + static_cast<long>(b * PairTwins::kMaxDeps + t.n_deps[b]));
    std::sort(got.begin(), got.end());
    CHECK(got == want);
  }
  // With one block per row and rows reaching many others, the lists overflow to kNoDeps.
  t.build(random_list(220, 200, 5), 200, 1);
  std::size_t overflow = 0;
  for (const auto c : t.n_deps) overflow += c == PairTwins::kNoDeps ? 1 : 0;
  CHECK(overflow > 0);
}
