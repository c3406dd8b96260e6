#pragma once
// One rank's own particles at an output time of a run over several ranks (run/partitioned_run.hpp),
// for the observers that write per-rank files (VTK pieces, run/vtk_observer.hpp). The rank's local
// system holds its owned particles and halo copies of its neighbours' and has just been evaluated
// at the output state, so the owned rows' fields (density, pressure, ...) are the whole system's;
// only the owned rows are listed, so every particle is written by exactly one rank. The probes
// sample from the pieces too, at their own times and at the output times
// (probes/probe_observer.hpp), and the case's measurements and the conservation sums reduce over
// them (run/piece_reduction.hpp). A serial run measures through one piece, the whole system
// (run/whole_piece.hpp).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "sphmol/rhs/sph_system.hpp"

namespace sphmol {

// The collectives of a piece's ranks (below), apart: what a run over ranks also lends to the pieces
// of its set-up, before the partition (run/start_piece.hpp). One rank: every collective returns its
// input (one_rank_collectives()).
struct PieceCollectives {
  int rank = 0, ranks = 1;
  // Collective: returns on a rank once every rank has called it (a piece on disk before the
  // collection that names it).
  std::function<void()> barrier;
  // Collective: the sum of `v` over the ranks (whether any rank has ghost images to write).
  std::function<std::uint64_t(std::uint64_t)> sum;
  // Collective: the smallest and the largest of `v` over the ranks (the probes' bins of the whole
  // fluid's box), and every rank's bytes concatenated in rank order on rank 0 (empty elsewhere):
  // the probes' terms, which rank 0 adds in the serial order.
  std::function<double(double)> min, max;
  std::function<std::vector<std::byte>(const std::vector<std::byte>&)> gather_bytes;
  // Collective: every rank's bytes concatenated in rank order, on every rank (the set-up's gathers
  // of a few particles: the force probes' walls, the fluid out of the domain at a restart).
  std::function<std::vector<std::byte>(const std::vector<std::byte>&)> all_gather_bytes;
  // Collective, element by element, on every rank: the largest of each value over the ranks (no NaN
  // may be passed), and the sum of each value modulo 2^64 (run/piece_reduction.hpp's exact sums).
  std::function<std::vector<double>(const std::vector<double>&)> max_each;
  std::function<std::vector<std::uint64_t>(const std::vector<std::uint64_t>&)> sum_each;
};

inline PieceCollectives one_rank_collectives() {
  PieceCollectives c;
  c.barrier = [] {};
  c.sum = [](std::uint64_t v) { return v; };
  c.min = [](double v) { return v; };
  c.max = [](double v) { return v; };
  c.gather_bytes = [](const std::vector<std::byte>& v) { return v; };
  c.all_gather_bytes = [](const std::vector<std::byte>& v) { return v; };
  c.max_each = [](const std::vector<double>& v) { return v; };
  c.sum_each = [](const std::vector<std::uint64_t>& v) { return v; };
  return c;
}

template <int D>
struct OwnedPiece : PieceCollectives {
  const SphSystem<D>* system = nullptr;  // owned + halo particles, fields of the output state
  const double* y = nullptr;             // that system's state (its own layout)
  // The owned rows of `system` (ascending, fluid rows first) and their global ids (the particle's
  // index in the whole scene, as the serial output's `id`).
  std::vector<std::size_t> fluid_rows, wall_rows;
  std::vector<std::int64_t> fluid_ids, wall_ids;
  // The generated ghost images of `system` whose sources are owned rows (in the system's order:
  // by source, then by mirror set). A rank mirrors its halo fluid too; those images are written by
  // the halo particles' owners, so every image is written once.
  std::vector<std::size_t> ghost_rows;
  // The global id of every fluid and wall row of `system` (owned and halo, ascending: the rows are
  // in global-id order; ghost images have none), for the probes' pairs that reach into the halo.
  std::vector<std::int64_t> row_ids;
};

}  // namespace sphmol
