#pragma once
// No-slip wall particles after Morris, Fox & Zhu (1997), J. Comput. Phys. 136:214, §3.2: for a
// fluid particle A at distance d_A from the wall and a wall particle B at depth d_B behind it, B is
// given the velocity that extends A's velocity linearly through the wall, v_B = v_w - (d_B/d_A)(v_A - v_w),
// so v_A - v_B = beta (v_A - v_w) with beta = min(beta_max, 1 + d_B/d_A). A linear shear profile is
// then reproduced exactly up to the wall, which prescribed wall velocities (beta = 1) do not: they
// put the effective no-slip plane about half a spacing inside the wall.
// The factor is stored per pair (Workspace::vfac) for both row directions of a fluid-wall pair.
// The cap: Morris et al. used beta_max = 1.5 against particles that come very close to the wall.
// On a lattice the first fluid row (d_A = dx/2) needs beta up to 1 + d_B/d_A = 4 for h = 1.3 dx, and
// capping it at 1.5 measurably moves the no-slip plane (Couette e_rms 2.7e-3 instead of 1.7e-5 at
// t = 0.5 s); the default 8 acts only on particles closer to the wall than d_B/7.
#include <algorithm>
#include <array>

#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

template <int D>
class MorrisWallVelocity final : public PairTermFor<D, MorrisWallVelocity<D>> {
 public:
  // wall_rows: also set the factor in the wall particles' rows, for terms that sum over wall rows
  // (the strain rate of physics/strain_rate.hpp); fluid rows always.
  MorrisWallVelocity(double beta_max, bool wall_rows) : beta_max_(beta_max), wall_rows_(wall_rows) {}
  std::string_view name() const override { return "morris_wall_velocity"; }
  // Sets the wall velocities only the viscous term reads: part of the implicit side of an IMEX split.
  bool implicit() const override { return true; }
  PairRows rows() const override { return wall_rows_ ? PairRows::all : PairRows::fluid; }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& pt = *w.particles;
    std::array<const double*, D> normal;  // turned with a rotating wall (Workspace::wall_normal)
    for (int d = 0; d < D; ++d) normal[d] = w.wall_normal[d] ? w.wall_normal[d] : pt.wall_normal[d].data();
    const bool wall_row = i >= w.n_fluid;
    std::uint32_t k = wall_row ? 0 : r.first_wall(w.n_fluid);
    for (; k < r.n; ++k) {
      const std::size_t j = r.j[k];
      const std::size_t b = wall_row ? i : j;  // the wall particle of the pair
      const double sign = wall_row ? -1.0 : 1.0;   // dx = x_i - x_j; we need x_fluid - x_wall
      double dA = -pt.wall_depth[b];
      for (int d = 0; d < D; ++d) dA += normal[d][b] * sign * r.dx[d][k];
      r.vfac[k] = dA > 0.0 ? std::min(beta_max_, 1.0 + pt.wall_depth[b] / dA) : beta_max_;
    }
  }

 private:
  double beta_max_;
  bool wall_rows_;
};

}  // namespace sphmol
