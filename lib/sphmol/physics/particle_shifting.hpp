#pragma once
// Fickian particle shifting (Lind, Xu, Stansby & Rogers 2012, J. Comput. Phys. 231:1499, eqs 21-24),
// written for the method of lines: particles move with v + du instead of v, down the gradient of the
// particle concentration C,
//   du_i = -A h U grad C_i,   grad C_i = sum_j V_j [1 + R (W_ij / W(dx))^n] grad_i W_ij,   V = m / rho
// (R = 0.2, n = 4: Lind's anti-clumping term, which pushes apart pairs closer than the spacing dx).
// Lind et al. shift by dr = -D grad C per step with D = A h |u| dt; divided by the step, that is the
// velocity above. U is one velocity for the whole flow (the scene's velocity scale), not Lind's
// per-particle |u|, so that particles are also kept apart at stagnation points, where a
// Lagrangian lattice is stretched most; A = 4 with U = U_max is the shift of the delta+-SPH model
// (Sun, Colagrossi, Marrone & Zhang 2017, Comput. Phys. Commun. 215:10: dr = -CFL Ma (2h)^2 grad C per
// step of dt = CFL h / c, i.e. du = -4 h U grad C).
// The particle values then belong to a point that moves with v + du, not with the fluid: the
// first-order Taylor correction of the shifted values of Lind et al. becomes, per unit time,
//   dv_i/dt += (du_i . grad) v_i = sum_j V_j (v_j - v_i) (du_i . grad_i W_ij)
// and the same for rho when the density is in the state (continuity); summation density needs none.
// h is the scene's smoothing length (with a variable h, the initial one: the shift only needs its
// scale). Neighbours that are wall particles enter with their volumes and velocities. Free surfaces (where
// grad C does not vanish in a uniform arrangement) are not treated: the loader refuses them.
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

template <int D>
class ParticleShifting final : public PairTermFor<D, ParticleShifting<D>> {
 public:
  static constexpr double kTensileR = 0.2;  // Lind et al. 2012, eq 24
  static constexpr int kTensileN = 4;
  // coefficient A, velocity U [m/s], smoothing length h, W(dx, h) for the anti-clumping ratio;
  // correction: the Taylor correction of v (and of rho in the state).
  ParticleShifting(double coefficient, double velocity, double h, double w_dx, bool correction)
      : k_(coefficient * h * velocity), inv_wdx_(w_dx > 0.0 ? 1.0 / w_dx : 0.0), correction_(correction) {}
  std::string_view name() const override { return "particle_shifting"; }
  bool zero_beyond_support() const override { return true; }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    double g[D] = {};
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      const double q = r.W[k] * inv_wdx_, q2 = q * q;
      const double f = m[j] / w.rho[j] * (1.0 + kTensileR * q2 * q2) * r.F[k];
      for (int d = 0; d < D; ++d) g[d] += f * r.dx[d][k];
    }
    double du[D];
    for (int d = 0; d < D; ++d) {
      du[d] = -k_ * g[d];
      w.dxdt[d][i] += du[d];
    }
    if (!correction_) return;
    double a[D] = {}, drho = 0.0;
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      double s = 0.0;  // du_i . grad_i W_ij
      for (int d = 0; d < D; ++d) s += du[d] * r.dx[d][k];
      s *= m[j] / w.rho[j] * r.F[k];
      for (int d = 0; d < D; ++d) a[d] += s * (w.v[d][j] - w.v[d][i]);
      drho += s * (w.rho[j] - w.rho[i]);
    }
    for (int d = 0; d < D; ++d) w.dvdt[d][i] += a[d];
    if (w.drhodt) w.drhodt[i] += drho;
  }

 private:
  double k_;        // A h U [m^2/s]
  double inv_wdx_;  // 1 / W(dx, h)
  bool correction_;
};

}  // namespace sphmol
