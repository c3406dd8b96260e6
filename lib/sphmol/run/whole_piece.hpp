#pragma once
// The whole system of a serial run as one piece (run/owned_piece.hpp): every particle is owned, the
// global ids are the rows, and the collectives of a single rank return their input. A case that
// measures from pieces (run/case.hpp) measures a serial run through it with the same code, and so
// the same sums, as a run over ranks.
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "sphmol/boundary/ghost_particles.hpp"
#include "sphmol/run/owned_piece.hpp"

namespace sphmol {

template <int D>
OwnedPiece<D> whole_piece(const SphSystem<D>& sys, const double* y) {
  OwnedPiece<D> p;
  p.system = &sys;
  p.y = y;
  const auto& P = sys.particles();
  // Generated particles (ghost images) follow the fluid and the walls; a system not evaluated yet
  // (over ranks the whole scene never is) has none.
  const auto* ghosts = dynamic_cast<const GhostGenerator<D>*>(sys.generator());
  const bool generated = ghosts && ghosts->base() >= P.n_fluid && ghosts->base() <= P.size();
  const std::size_t base = generated ? ghosts->base() : P.size();
  p.fluid_rows.resize(P.n_fluid);
  std::iota(p.fluid_rows.begin(), p.fluid_rows.end(), std::size_t{0});
  p.wall_rows.resize(base - P.n_fluid);
  std::iota(p.wall_rows.begin(), p.wall_rows.end(), P.n_fluid);
  p.fluid_ids.assign(p.fluid_rows.begin(), p.fluid_rows.end());
  p.wall_ids.assign(p.wall_rows.begin(), p.wall_rows.end());
  for (std::size_t g = base; g < P.size(); ++g) p.ghost_rows.push_back(g);
  p.row_ids.resize(base);
  std::iota(p.row_ids.begin(), p.row_ids.end(), std::int64_t{0});
  static_cast<PieceCollectives&>(p) = one_rank_collectives();
  return p;
}

}  // namespace sphmol
