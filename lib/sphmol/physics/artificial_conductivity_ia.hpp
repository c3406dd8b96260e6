#pragma once
// Artificial thermal conductivity of Price (2008) (physics/artificial_conductivity.hpp) with the
// integral approach's gradients: r_hat_ij . grad_i W_ij replaced by r_hat_ij . Abar_ij, the mean IA
// vector of physics/artificial_viscosity_ia.hpp,
//   de_i/dt += sum_j (m_j / rhobar_ij) alpha_u v_sig^u (e_i - e_j) r_hat_ij . Abar_ij,
//   r_hat_ij . Abar_ij = -dx_ij . (W_i C_i + W_j C_j) dx_ij / (2 |dx_ij|)  (< 0 for positive definite C),
// so heat still flows from the hotter to the colder particle, and the pair's two contributions, times
// m_i and m_j, cancel (r_hat . Abar is symmetric in i, j; e_i - e_j is not): total energy conserved.
#include <cmath>
#include <memory>

#include "sphmol/physics/integral_approach_matrix.hpp"

namespace sphmol {

template <int D>
class ArtificialConductivityIA final : public PairTermFor<D, ArtificialConductivityIA<D>> {
 public:
  ArtificialConductivityIA(double alpha_u, std::shared_ptr<const IntegralApproachField<D>> C)
      : alpha_u_(alpha_u), C_(std::move(C)) {}
  std::string_view name() const override { return "artificial_conductivity_integral_approach"; }
  bool zero_beyond_support() const override { return C_->kernel == nullptr; }  // W(r, h_i) may reach past kappa h_ij
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
        double de = 0.0;
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      double dx[D], ci[D], cj[D], r2 = 0.0, q = 0.0;
      for (int d = 0; d < D; ++d) {
        dx[d] = r.dx[d][k];
        r2 += dx[d] * dx[d];
      }
      if (r2 <= 0.0) continue;
      double Wi, Wj;
      C_->weights(w, i, j, r.W[k], r2, Wi, Wj);
      ia_times<D>(C_->of(i), dx, ci);
      ia_times<D>(C_->of(i, j), dx, cj);
      for (int d = 0; d < D; ++d) q += dx[d] * (Wi * ci[d] + Wj * cj[d]);
      const double rhobar = 0.5 * (w.rho[i] + w.rho[j]);
      const double vsig = std::sqrt(std::abs(w.p[i] - w.p[j]) / rhobar);
      de -= m[j] / rhobar * vsig * (w.e[i] - w.e[j]) * 0.5 * q / std::sqrt(r2);
    }
    w.dedt[i] += alpha_u_ * de;
  }

 private:
  double alpha_u_;
  std::shared_ptr<const IntegralApproachField<D>> C_;
};

}  // namespace sphmol
