#pragma once
// No-slip velocity of wall particles after Adami, Hu & Adams (2012), J. Comput. Phys. 231:7057,
// eqs. 22-23: the fluid velocity Shepard-interpolated to the wall particle,
//   v~_w = sum_f v_f W_wf / sum_f W_wf,
// is mirrored about the wall's own velocity, u_w = 2 v_wall - v~_w, so that the velocity is
// extrapolated linearly through the wall and the no-slip plane lies on the wall surface (prescribed
// wall velocities put it about half a spacing inside). Unlike Morris et al. (1997,
// morris_wall_velocity.hpp) it needs no wall normal or depth, so it holds at corners and on curved or
// moving walls alike. Adami et al. use u_w in the viscous term only: continuity and the pressure
// term keep the wall's own velocity, so the wall does not compress the fluid next to it. The
// viscous terms read it from Workspace::v_viscous; fluid entries are the fluid velocities.
// Wall rows of the pair list hold exactly the fluid neighbours (neighbors/pair_list.hpp). A wall
// particle without fluid neighbours keeps its own velocity.
#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class AdamiWallVelocity final : public Term<D> {
 public:
  std::string_view name() const override { return "adami_wall_velocity"; }
  // Sets the wall velocities only the viscous term reads: part of the implicit side of an IMEX split.
  bool implicit() const override { return true; }
  bool reads_stored_pairs() const override { return true; }
  void apply(Workspace<D>& w) const override {
    const auto& P = w.pairs;
    for (int d = 0; d < D; ++d) {
      w.v_viscous[d].resize(w.n);
      std::copy(w.v[d].begin(), w.v[d].begin() + static_cast<std::ptrdiff_t>(w.n), w.v_viscous[d].begin());
    }
    for (std::size_t i = w.n_fluid; i < w.n; ++i) {
      if (w.particles->kind[i] != Kind::Wall) continue;
      double sw = 0.0, sv[D] = {};
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
        const std::uint32_t j = P.j[k];
        sw += w.W[k];
        for (int d = 0; d < D; ++d) sv[d] += w.v[d][j] * w.W[k];
      }
      if (sw <= 0.0) continue;
      for (int d = 0; d < D; ++d) w.v_viscous[d][i] = 2.0 * w.v[d][i] - sv[d] / sw;
    }
  }
};

}  // namespace sphmol
