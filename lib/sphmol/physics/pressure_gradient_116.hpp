#pragma once
// Pressure part of the symmetric momentum equation, seed 000 eq 116 (seed 003 eq 2.62):
//   dv_i/dt -= sum_j m_j (p_i + p_j) / (rho_i rho_j) grad_i W_ij
// Antisymmetric in i, j like eq 117, so pair forces conserve momentum; pairs with the energy
// equation in its eq 2.65 form.
#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class PressureGradient116 final : public Term<D> {
 public:
  std::string_view name() const override { return "pressure_gradient_116"; }
  void apply(Workspace<D>& w) const override {
    const auto& P = w.pairs;
    const auto& m = w.particles->mass;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < w.n_fluid; ++i) {
      double a[D] = {};
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
        const std::uint32_t j = P.j[k];
        const double s = m[j] * (w.p[i] + w.p[j]) / (w.rho[i] * w.rho[j]) * w.F[k];
        for (int d = 0; d < D; ++d) a[d] -= s * w.dx[d][k];
      }
      for (int d = 0; d < D; ++d) w.dvdt[d][i] += a[d];
    }
  }
};

}  // namespace sphmol
