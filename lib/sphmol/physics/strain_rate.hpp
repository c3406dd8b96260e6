#pragma once
// Strain-rate tensor from velocity differences, seed 000 eq 122 / seed 002 eq 13:
//   eps_ab(i) = sum_j V_j [ v_b(ji) dW/dx_a + v_a(ji) dW/dx_b ] - 2/3 delta_ab sum_j V_j v_c(ji) dW/dx_c
// with V_j = m_j / rho_j and v(ji) = v_j - v_i. Computed for wall rows too, because the momentum
// equation (000 eq 117) needs eps at the wall neighbours; wall rows see only fluid particles, and a
// missing wall-wall pair contributes nothing for walls that move together. Velocity differences of
// fluid-wall pairs are scaled by the wall model's factor (rhs/workspace.hpp, vfac).
#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class StrainRate final : public Term<D> {
 public:
  std::string_view name() const override { return "strain_rate"; }
  void apply(Workspace<D>& w) const override {
    const auto& P = *w.pairs;
    const auto& m = w.particles->mass;
    for (std::size_t i = 0; i < w.n; ++i) {
      double g[D][D] = {};  // g[a][b] = sum_j V_j v_b(ji) dW/dx_a
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
        const std::uint32_t j = P.j[k];
        const double s = m[j] / w.rho[j] * w.F[k];
        double dx[D], dv[D];
        for (int d = 0; d < D; ++d) {
          dx[d] = w.separation(d, i, j);
          dv[d] = w.vfac[k] * (w.v[d][j] - w.v[d][i]);
        }
        for (int a = 0; a < D; ++a)
          for (int b = 0; b < D; ++b) g[a][b] += s * dv[b] * dx[a];
      }
      double div = 0.0;
      for (int a = 0; a < D; ++a) div += g[a][a];
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b)
          w.strain[a * D + b][i] = g[a][b] + g[b][a] - (a == b ? 2.0 / 3.0 * div : 0.0);
    }
  }
};

}  // namespace sphmol
