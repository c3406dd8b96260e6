#pragma once
// Pressure part of the symmetric momentum equation, seed 000 eq 117 (seed 002 eq 12):
//   dv_i/dt -= sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2) grad_i W_ij
#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class PressureGradient117 final : public Term<D> {
 public:
  std::string_view name() const override { return "pressure_gradient_117"; }
  void apply(Workspace<D>& w) const override {
    const auto& P = w.pairs;
    const auto& m = w.particles->mass;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < w.n_fluid; ++i) {
      const double pi = w.p[i] / (w.rho[i] * w.rho[i]);
      double a[D] = {};
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
        const std::uint32_t j = P.j[k];
        const double s = m[j] * (pi + w.p[j] / (w.rho[j] * w.rho[j])) * w.F[k];
        for (int d = 0; d < D; ++d) a[d] -= s * w.dx[d][k];
      }
      for (int d = 0; d < D; ++d) w.dvdt[d][i] += a[d];
    }
  }
};

}  // namespace sphmol
