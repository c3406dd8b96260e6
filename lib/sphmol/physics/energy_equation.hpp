#pragma once
// Energy equation of an inviscid fluid, pressure work only (Niedoba 2012, §2.2.4):
//   eq 2.66 (Form117): de_i/dt = 1/2 sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2) v_ij . grad_i W_ij
//   eq 2.65 (Form116): de_i/dt = 1/2 sum_j m_j (p_i + p_j)/(rho_i rho_j) v_ij . grad_i W_ij
// Each form is the work of the matching momentum equation (Vukčević 2012, eq 117 / 116), so the
// total energy sum m (e + v^2/2) is conserved by the pair sums. The artificial viscosity adds its
// own work (physics/artificial_viscosity.hpp, eq 2.72).
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

enum class EnergyForm { symmetric_116, symmetric_117 };

template <int D, EnergyForm Form>
class EnergyEquation final : public PairTermFor<D, EnergyEquation<D, Form>> {
 public:
  std::string_view name() const override {
    return Form == EnergyForm::symmetric_117 ? "energy_equation_2.66" : "energy_equation_2.65";
  }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    {
      double de = 0.0;
      for (std::uint32_t k = 0; k < r.n; ++k) {
        const std::uint32_t j = r.j[k];
        double vx = 0.0;
        for (int d = 0; d < D; ++d) vx += (w.v[d][i] - w.v[d][j]) * r.dx[d][k];
        double coef;
        if constexpr (Form == EnergyForm::symmetric_117)
          coef = w.p[i] / (w.rho[i] * w.rho[i]) + w.p[j] / (w.rho[j] * w.rho[j]);
        else
          coef = (w.p[i] + w.p[j]) / (w.rho[i] * w.rho[j]);
        de += m[j] * coef * vx * r.F[k];
      }
      w.dedt[i] += 0.5 * de;
    }
  }
};

}  // namespace sphmol
