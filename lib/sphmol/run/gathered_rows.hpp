#pragma once
// Rows of a per-particle file (one per fluid particle: profiles, pressure columns) from every rank's
// own particles, collected on rank 0 for a case that measures from pieces (run/owned_piece.hpp):
// the rows travel, not the whole state. The caller orders them (by global id, or by height and id),
// so that the file does not depend on the split.
#include <cstring>
#include <type_traits>
#include <vector>

#include "sphmol/run/owned_piece.hpp"

namespace sphmol {

// Collective: every rank's rows, concatenated in rank order, on rank 0 (empty elsewhere; a serial
// run's one piece returns its own).
template <int D, class Row>
std::vector<Row> gather_rows(const OwnedPiece<D>& piece, const std::vector<Row>& rows) {
  static_assert(std::is_trivially_copyable_v<Row>);
  std::vector<std::byte> mine(rows.size() * sizeof(Row));
  if (!rows.empty()) std::memcpy(mine.data(), rows.data(), mine.size());
  const std::vector<std::byte> all = piece.gather_bytes(mine);
  std::vector<Row> out(all.size() / sizeof(Row));
  if (!out.empty()) std::memcpy(out.data(), all.data(), out.size() * sizeof(Row));
  return out;
}

// Collective: whether the run writes files (its sink is enabled on rank 0 only), the same on every rank.
template <int D>
bool writes_files(const OwnedPiece<D>& piece, bool enabled_here) {
  return piece.max(enabled_here ? 1.0 : 0.0) > 0.0;
}

}  // namespace sphmol
