#pragma once
// The bookkeeping of symmetric pair passes (rhs/fused_pair_pass.hpp): where each fluid pair of a
// Verlet list is evaluated and where its other direction finds the result. Rows are sorted with
// j != i (neighbors/pair_list.hpp), so a fluid row i splits into a lower part (j < i: fluid
// neighbours of smaller index) and an upper part (j > i: fluid neighbours of larger index, then the
// walls). A pair is evaluated once, in the upper part of the row of its smaller index, into one
// record per entry; the row of its larger index reads that record through `twin`. A pair found in
// one direction only (a list that is not symmetric) leaves `complete` false, and the pass then
// evaluates every row in full instead.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "sphmol/neighbors/pair_list.hpp"

namespace sphmol {

struct PairTwins {
  std::vector<std::uint32_t> upper;   // per row: the first Verlet entry with j > i
  std::vector<std::uint32_t> record;  // per row: its first record (the upper parts numbered in row order); rows + 1
  std::vector<std::uint32_t> twin;    // per Verlet entry of a lower part: the record of the same pair in row j
  // Per aligned block of `block` rows, the other blocks its rows' lower parts reach (sorted; at most
  // kMaxDeps, in deps[b * kMaxDeps ...]): what must be ready before the block's rows read twins.
  // n_deps[b] = kNoDeps when they reach more blocks than that (the rows are then checked one by one).
  static constexpr std::uint32_t kMaxDeps = 32, kNoDeps = ~0u;
  std::vector<std::uint32_t> n_deps, deps;
  bool complete = false;

  std::size_t rows() const { return upper.size(); }
  std::size_t records() const { return record.empty() ? 0 : record.back(); }

  // The steps of build(), for callers that run the per-row ones on several threads: size, then
  // find_upper for every row, then place_records once, then find_twins for ranges of rows that
  // cover the table (each returns false when a row of its range has a pair whose reverse is missing).
  void size(std::size_t rows, std::size_t entries) {
    upper.resize(rows);
    record.resize(rows + 1);
    twin.resize(entries);
    next_.resize(rows);
  }
  void find_upper(const PairList& list, std::size_t i) {
    const std::uint32_t* row = list.j.data();
    upper[i] = static_cast<std::uint32_t>(
        std::upper_bound(row + list.offset[i], row + list.offset[i + 1], static_cast<std::uint32_t>(i)) - row);
  }
  void place_records(const PairList& list) {
    record[0] = 0;
    for (std::size_t i = 0; i < upper.size(); ++i) record[i + 1] = record[i] + (list.offset[i + 1] - upper[i]);
  }
  // The twins of the lower parts of rows [a, b), in one ascending pass over the rows that reach
  // them instead of a search in row j per entry: rows are sorted, so the rows i < j that hold j in
  // their upper parts come, by ascending i, in the order of j's lower part, and a cursor per row
  // (next_, each range writing its own rows) pairs them up. A lower entry with no reverse gets twin
  // 0 and makes the result false; an upper entry with no reverse is skipped (its record is summed
  // by its own row only, as the full row would).
  bool find_twins(const PairList& list, std::size_t a, std::size_t b) {
    if (a >= b) return true;
    const std::uint32_t* row = list.j.data();
    const std::uint32_t* off = list.offset.data();
    std::uint32_t* const next = next_.data();
    auto first = static_cast<std::uint32_t>(b);  // the smallest row that rows [a, b) reach downwards
    for (std::size_t j = a; j < b; ++j) {
      next[j] = off[j];
      if (off[j] < upper[j]) first = std::min(first, row[off[j]]);
    }
    const auto lo_row = static_cast<std::uint32_t>(a), hi_row = static_cast<std::uint32_t>(b);
    bool found = true;
    for (std::uint32_t i = first; i < hi_row; ++i) {
      const std::uint32_t* const up = row + upper[i];
      const std::uint32_t* const end = row + off[i + 1];
      const std::uint32_t* at = i >= lo_row ? up : std::lower_bound(up, end, lo_row);
      for (; at != end && *at < hi_row; ++at) {
        const std::uint32_t j = *at;
        std::uint32_t c = next[j];
        for (; c < upper[j] && row[c] < i; ++c) {
          twin[c] = 0;
          found = false;
        }
        if (c < upper[j] && row[c] == i) twin[c++] = record[i] + static_cast<std::uint32_t>(at - up);
        next[j] = c;
      }
    }
    for (std::size_t j = a; j < b; ++j)
      for (std::uint32_t c = next[j]; c < upper[j]; ++c) {
        twin[c] = 0;
        found = false;
      }
    return found;
  }

  // After find_upper for every row: size the block tables, then find_block_deps for every block.
  std::size_t size_blocks(std::size_t block) {
    const std::size_t blocks = (upper.size() + block - 1) / block;
    n_deps.resize(blocks);
    deps.resize(blocks * kMaxDeps);
    return blocks;
  }
  void find_block_deps(const PairList& list, std::size_t block, std::size_t b) {
    std::uint32_t* reach = deps.data() + b * kMaxDeps;
    std::uint32_t n = 0;
    // A row's lower part is ascending, so its entries of one block come together: the block of the
    // entry before is skipped without searching the list.
    auto last = static_cast<std::uint32_t>(b);
    for (std::size_t i = b * block; i < std::min(upper.size(), (b + 1) * block) && n != kNoDeps; ++i)
      for (std::uint32_t q = list.offset[i]; q < upper[i]; ++q) {
        const auto c = static_cast<std::uint32_t>(list.j[q] / block);
        if (c == last) continue;
        last = c;
        if (c == b || std::find(reach, reach + n, c) != reach + n) continue;
        if (n == kMaxDeps) {
          n = kNoDeps;
          break;
        }
        reach[n++] = c;
      }
    n_deps[b] = n;
  }

  // The tables for the first `rows` rows of `list` (the fluid rows), on one thread.
  void build(const PairList& list, std::size_t rows, std::size_t block = 32) {
    size(rows, list.pairs());
    for (std::size_t i = 0; i < rows; ++i) find_upper(list, i);
    place_records(list);
    for (std::size_t b = 0, blocks = size_blocks(block); b < blocks; ++b) find_block_deps(list, block, b);
    complete = find_twins(list, 0, rows);
  }

 private:
  std::vector<std::uint32_t> next_;  // find_twins' cursor in each row's lower part
};

}  // namespace sphmol
