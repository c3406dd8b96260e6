#pragma once
// The particles a rank starts a run with, as a piece (run/owned_piece.hpp), for what the run's set-up
// sums or gathers over the whole scene before the partition: the conservation log's first record and
// the fluid mass (exact sums, run/piece_reduction.hpp), the fluid out of the domain at a restart
// (run/outflow.hpp), the probes' box and the force probes' walls (probes/probe_observer.hpp). Rank r of
// R starts with the global indices [N r / R, N (r + 1) / R) (core/scene_share.hpp): its system is
// either that share alone (Case::build_share) or the whole scene, of which the piece lists those rows.
// A serial run is one rank holding the whole scene: its piece is every particle.
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>

#include "sphmol/core/scene_share.hpp"
#include "sphmol/run/owned_piece.hpp"

namespace sphmol {

// y: sys's state (its own layout). Before any evaluation (no generated particles).
template <int D>
OwnedPiece<D> start_piece(const SphSystem<D>& sys, const double* y, SceneShare share, PieceCollectives collectives) {
  OwnedPiece<D> p;
  static_cast<PieceCollectives&>(p) = std::move(collectives);
  p.system = &sys;
  p.y = y;
  const auto& P = sys.particles();
  const auto whole = sys.whole_scene();
  const std::size_t n = sys.base_particles();
  const std::size_t lo = share.begin(whole.size), hi = share.end(whole.size);
  // The system's rows [lo - first, hi - first) are the share's.
  const std::size_t first = whole.first;
  if (lo < first || hi > first + n || (sys.is_share() && (lo != first || hi != first + n)))
    throw std::logic_error("start_piece: the system holds particles [" + std::to_string(first) + ", " +
                           std::to_string(first + n) + "), not share " + std::to_string(share.index) + " of " +
                           std::to_string(share.count) + " of " + std::to_string(whole.size));
  for (std::size_t row = lo - first; row < hi - first; ++row) {
    const bool fluid = row < P.n_fluid;
    (fluid ? p.fluid_rows : p.wall_rows).push_back(row);
    (fluid ? p.fluid_ids : p.wall_ids).push_back(static_cast<std::int64_t>(row + first));
  }
  p.row_ids.resize(n);
  std::iota(p.row_ids.begin(), p.row_ids.end(), static_cast<std::int64_t>(first));
  return p;
}

}  // namespace sphmol
