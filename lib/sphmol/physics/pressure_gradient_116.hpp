#pragma once
// Pressure part of the symmetric momentum equation, Vukčević 2012, eq 116 (Niedoba 2012, eq 2.62):
//   dv_i/dt -= sum_j m_j (p_i + p_j) / (rho_i rho_j) grad_i W_ij
// Antisymmetric in i, j like eq 117, so pair forces conserve momentum; pairs with the energy
// equation in its eq 2.65 form.
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

template <int D>
class PressureGradient116 final : public PairTermFor<D, PressureGradient116<D>> {
 public:
  std::string_view name() const override { return "pressure_gradient_116"; }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    double a[D] = {};
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      const double s = m[j] * (w.p[i] + w.p[j]) / (w.rho[i] * w.rho[j]) * r.F[k];
      for (int d = 0; d < D; ++d) a[d] -= s * r.dx[d][k];
    }
    for (int d = 0; d < D; ++d) w.dvdt[d][i] += a[d];
  }
};

}  // namespace sphmol
