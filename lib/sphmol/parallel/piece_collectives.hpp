#pragma once
// The collectives of a piece (run/owned_piece.hpp) over the ranks of a communicator.
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/run/owned_piece.hpp"

namespace sphmol::parallel {

// `comm` must outlive every copy of the functions.
inline PieceCollectives piece_collectives(const Communicator& comm) {
  PieceCollectives c;
  c.rank = comm.rank();
  c.ranks = comm.size();
  const Communicator* k = &comm;
  c.barrier = [k] { k->barrier(); };
  c.sum = [k](std::uint64_t v) { return k->sum(v); };
  c.min = [k](double v) { return k->min(v); };
  c.max = [k](double v) { return k->max(v); };
  c.gather_bytes = [k](const std::vector<std::byte>& v) { return k->gather_v(v, 0); };
  c.all_gather_bytes = [k](const std::vector<std::byte>& v) { return k->all_gather_v(v); };
  c.max_each = [k](const std::vector<double>& v) { return k->max(v); };
  c.sum_each = [k](const std::vector<std::uint64_t>& v) { return k->sum(v); };
  return c;
}

}  // namespace sphmol::parallel
