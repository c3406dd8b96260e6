#pragma once
// Continuity density, Niedoba 2012, eq 2.61 (Vukčević 2012, eq 108):
//   drho_i/dt = sum_j m_j v_ij . grad_i W_ij,   v_ij = v_i - v_j
// rho is part of the ODE state; this term writes its rate. Wall neighbours enter with their
// prescribed velocity. No edge effect at density jumps (Niedoba 2012, §3.3), but mass is not
// conserved exactly (the density no longer follows from the positions).
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

// The sum of Niedoba 2012, eq 2.61 over one row (also used for dynamic wall particles).
template <int D>
inline double continuity_rate(const Workspace<D>& w, std::size_t i, const PairRow<D>& r) {
  const auto& m = w.particles->mass;
  double s = 0.0;
  for (std::uint32_t k = 0; k < r.n; ++k) {
    const std::uint32_t j = r.j[k];
    double vdx = 0.0;
    for (int d = 0; d < D; ++d) vdx += (w.v[d][i] - w.v[d][j]) * r.dx[d][k];
    s += m[j] * vdx * r.F[k];
  }
  return s;
}

template <int D>
class ContinuityDensity final : public PairTermFor<D, ContinuityDensity<D>> {
 public:
  std::string_view name() const override { return "continuity_density"; }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const { w.drhodt[i] += continuity_rate(w, i, r); }
};

}  // namespace sphmol
