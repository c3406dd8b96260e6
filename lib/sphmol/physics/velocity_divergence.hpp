#pragma once
// The SPH velocity divergence per fluid particle (Monaghan 1992, sec. 2, applied to v):
//   div_i = sum_j (m_j / rho_j) (v_j - v_i) . grad_i W_ij,
// exact for a linear velocity field on a lattice whose particle volumes satisfy the gradient moment
// sum_j V_j (x_j - x_i) grad_i W_ij^T = I (discretization.particle_mass: gradient), and within the
// moment's deviation otherwise. Wall particles enter with their own (prescribed) velocity, as in the
// continuity equation, not with the no-slip velocity a wall model gives the viscous terms: that velocity
// reverses the tangential motion across the wall, and the divergence of a field reversed that way is not
// the fluid's (-du/dx + dv/dy beside a wall along x), which at a moving lid's corners drove the cavity
// unstable. (Ghost images carry that reversed velocity too, so the loader refuses the bulk viscosity
// with ghost walls; a scene's mirror planes need boundary: ghost.) The bulk viscous pressure (physics/bulk_viscosity.hpp) reads div_j of every
// neighbour while summing row i, so the divergences are a pass of their own (a term that feeds
// neighbours ends a fused pass, rhs/pair_pass_plan.hpp).
#include <memory>
#include <vector>

#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

// div v per fluid particle (workspace index): written by VelocityDivergence, read by BulkViscosity.
using VelocityDivergenceField = std::vector<double>;

template <int D>
class VelocityDivergence final : public PairTermFor<D, VelocityDivergence<D>> {
 public:
  explicit VelocityDivergence(std::shared_ptr<VelocityDivergenceField> div) : div_(std::move(div)) {}
  std::string_view name() const override { return "velocity_divergence"; }
  bool feeds_neighbours() const override { return true; }
  void prepare(Workspace<D>& w) const override { div_->resize(w.n_fluid); }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    double s = 0.0;  // sum_j V_j F_ij (v_j - v_i) . (x_i - x_j); grad_i W_ij = F_ij (x_i - x_j)
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      double dv = 0.0;
      for (int d = 0; d < D; ++d) dv += (w.v[d][j] - w.v[d][i]) * r.dx[d][k];
      s += m[j] / w.rho[j] * r.F[k] * dv;
    }
    (*div_)[i] = s;
  }

 private:
  std::shared_ptr<VelocityDivergenceField> div_;
};

}  // namespace sphmol
