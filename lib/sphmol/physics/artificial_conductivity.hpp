#pragma once
// Artificial thermal conductivity of Price (2008, J. Comput. Phys. 227:10040: the dissipative term in
// the thermal energy and its signal speed for hydrodynamics without gravity):
//   de_i/dt += sum_j (m_j / rhobar_ij) alpha_u v_sig^u (e_i - e_j) r_hat_ij . grad_i W_ij,
//   v_sig^u = sqrt(|p_i - p_j| / rhobar_ij),   rhobar_ij = (rho_i + rho_j)/2.
// It conducts only where p jumps (v_sig^u ~ sqrt(|p_i - p_j|)): at a contact discontinuity whose
// smoothed density puts a pressure "blip" across the jump in e, it spreads e until the pressures
// balance, and then stops (Price 2008); across a contact in pressure balance it does nothing. r_hat . grad W = dW/dr = r F_ij < 0,
// so heat flows from the hotter to the colder particle of each pair; the pair contributions
// m_i m_j (...) are antisymmetric, so sum_i m_i de_i/dt = 0 (total energy conserved) when every
// neighbour is itself a fluid particle. Wall particles (fixed e) exchange heat one way only.
#include <cmath>

#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

template <int D>
class ArtificialConductivity final : public PairTermFor<D, ArtificialConductivity<D>> {
 public:
  explicit ArtificialConductivity(double alpha_u) : alpha_u_(alpha_u) {}
  std::string_view name() const override { return "artificial_conductivity"; }
  bool zero_beyond_support() const override { return true; }  // every contribution carries F
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    double de = 0.0;
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      double r2 = 0.0;
      for (int d = 0; d < D; ++d) r2 += r.dx[d][k] * r.dx[d][k];
      const double rhobar = 0.5 * (w.rho[i] + w.rho[j]);
      const double vsig = std::sqrt(std::abs(w.p[i] - w.p[j]) / rhobar);
      de += m[j] / rhobar * vsig * (w.e[i] - w.e[j]) * std::sqrt(r2) * r.F[k];
    }
    w.dedt[i] += alpha_u_ * de;
  }

 private:
  double alpha_u_;
};

}  // namespace sphmol
