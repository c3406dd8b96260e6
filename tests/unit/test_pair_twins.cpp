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

TEST_CASE("pair twins: tables found in ranges of rows equal those of one range, for any split", "[unit][neighbors]") {
  // The pass over the rows that reach a range starts below it (at the smallest lower neighbour of
  // its rows) and stops at its end; splits into 2, 3 and 7 ranges (make_twins gives each thread one)
  // must give the one-range tables, for a symmetric list and for one missing a reverse.
  const std::size_t n = 140, nf = 120;
  PairList sym = random_list(n, nf, 13);
  PairList broken = sym;
  // Row 70 loses its first upper entry; the pair stays in the lower part of a row above 70, which
  // may lie in another range.
  PairTwins probe;
  probe.build(broken, nf);
  REQUIRE(probe.upper[70] < broken.offset[71]);
  broken.j.erase(broken.j.begin() + probe.upper[70]);
  for (std::size_t i = 71; i < broken.offset.size(); ++i) --broken.offset[i];
  for (const PairList* list : {&sym, &broken}) {
    PairTwins whole;
    whole.build(*list, nf);
    CHECK(whole.complete == (list == &sym));
    for (const std::size_t parts : {2u, 3u, 7u}) {
      INFO("ranges " << parts);
      PairTwins t;
      t.size(nf, list->pairs());
      for (std::size_t i = 0; i < nf; ++i) t.find_upper(*list, i);
      t.place_records(*list);
      bool complete = true;
      for (std::size_t p = 0; p < parts; ++p) complete = t.find_twins(*list, nf * p / parts, nf * (p + 1) / parts) && complete;
      CHECK(complete == whole.complete);
      CHECK(t.upper == whole.upper);
      CHECK(t.record == whole.record);
      CHECK(t.twin == whole.twin);
    }
  }
}

TEST_CASE("pair twins: an upper entry whose reverse is missing leaves the tables complete", "[unit][neighbors]") {
  // Its record is summed by its own row only, as that row's full evaluation would: the pass stays
  // symmetric. The lower entries of the other rows keep their twins.
  PairList list = random_list(30, 30, 5);
  PairTwins t;
  t.build(list, 30);
  REQUIRE(t.complete);
  // Row j loses the lower entry of its smallest neighbour i: i keeps j in its upper part.
  std::size_t j = 29;
  while (list.offset[j] == t.upper[j]) --j;
  list.j.erase(list.j.begin() + list.offset[j]);
  for (std::size_t k = j + 1; k < list.offset.size(); ++k) --list.offset[k];
  PairTwins u;
  u.build(list, 30);
  CHECK(u.complete);
  for (std::size_t i = 0; i < 30; ++i)
    for (std::uint32_t q = list.offset[i]; q < u.upper[i]; ++q) {
      const std::uint32_t r = u.twin[q];
      REQUIRE(r < u.records());
      const std::uint32_t other = list.j[q];  // row of the record, at its entry for i
      REQUIRE(r >= u.record[other]);
      REQUIRE(r < u.record[other + 1]);
      CHECK(list.j[u.upper[other] + (r - u.record[other])] == i);
    }
}
