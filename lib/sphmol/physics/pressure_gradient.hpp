#pragma once
// Pressure part of the symmetric momentum equation, Vukčević 2012, eq 117 (Vukčević et al. 2012, eq
// 12):
//   dv_i/dt -= sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2) grad_i W_ij
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

template <int D>
class PressureGradient117 final : public PairTermFor<D, PressureGradient117<D>> {
 public:
  std::string_view name() const override { return "pressure_gradient_117"; }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    const double pi = w.p[i] / (w.rho[i] * w.rho[i]);
    double a[D] = {};
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      const double s = m[j] * (pi + w.p[j] / (w.rho[j] * w.rho[j])) * r.F[k];
      for (int d = 0; d < D; ++d) a[d] -= s * r.dx[d][k];
    }
    for (int d = 0; d < D; ++d) w.dvdt[d][i] += a[d];
  }
};

}  // namespace sphmol
