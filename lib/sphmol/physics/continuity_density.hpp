#pragma once
// Continuity density, Niedoba 2012, eq 2.61 (Vukčević 2012, eq 108):
//   drho_i/dt = sum_j m_j v_ij . grad_i W_ij,   v_ij = v_i - v_j
// rho is part of the ODE state; this term writes its rate. Wall neighbours enter with their
// prescribed velocity. No edge effect at density jumps (Niedoba 2012, §3.3), but mass is not
// conserved exactly (the density no longer follows from the positions).
//
// The volume-weighted form of Colagrossi & Landrini (2003, J. Comput. Phys. 191:448, their
// continuity equation for interfaces between fluids of different density):
//   drho_i/dt = rho_i sum_j (m_j / rho_j) v_ij . grad_i W_ij
// Both estimate -rho div v; they differ where rho jumps inside the support. There the mass-weighted
// sum gives a light particle beside dense gas the dense side's m_j: a velocity difference across the
// jump changes its density rho_dense / rho_i times faster than -rho div v (8x at Sod's jump). The
// light particle that the pressure jump pushes away from the dense gas then loses density, and with
// it p, faster than it moves; p / rho^2 = e (gamma - 1) / rho grows as rho falls, so it is pushed
// harder: the run-away that ejects the first light particle of a sharp 2D Sod start. The volume
// weights give every particle the relative rate (1 / rho_i) drho_i/dt of the local div v.
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

// Sum_j w_j v_ij . grad_i W_ij over one row, w_j = m_j (Volume = false) or m_j / rho_j.
template <int D, bool Volume>
inline double weighted_divergence_sum(const Workspace<D>& w, std::size_t i, const PairRow<D>& r) {
  const auto& m = w.particles->mass;
  double s = 0.0;
  for (std::uint32_t k = 0; k < r.n; ++k) {
    const std::uint32_t j = r.j[k];
    double vdx = 0.0;
    for (int d = 0; d < D; ++d) vdx += (w.v[d][i] - w.v[d][j]) * r.dx[d][k];
    const double wj = Volume ? m[j] / w.rho[j] : m[j];
    s += wj * vdx * r.F[k];
  }
  return s;
}

// The sum of Niedoba 2012, eq 2.61 over one row (also used for dynamic wall particles).
template <int D>
inline double continuity_rate(const Workspace<D>& w, std::size_t i, const PairRow<D>& r) {
  return weighted_divergence_sum<D, false>(w, i, r);
}

// The sum of the volume-weighted form (Colagrossi & Landrini 2003) over one row.
template <int D>
inline double continuity_rate_volume(const Workspace<D>& w, std::size_t i, const PairRow<D>& r) {
  return w.rho[i] * weighted_divergence_sum<D, true>(w, i, r);
}

// Volume = true: the Colagrossi & Landrini (2003) weights (discretization.continuity: volume).
template <int D, bool Volume = false>
class ContinuityDensity final : public PairTermFor<D, ContinuityDensity<D, Volume>> {
 public:
  std::string_view name() const override { return Volume ? "continuity_density_volume" : "continuity_density"; }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    if constexpr (Volume) w.drhodt[i] += continuity_rate_volume(w, i, r);
    else w.drhodt[i] += continuity_rate(w, i, r);
  }
};

}  // namespace sphmol
