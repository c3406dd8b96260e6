#pragma once
// Pressure part of the momentum equation with the integral approach's gradients (Garcia-Senz,
// Cabezón & Escartín 2012, §2; for the Euler equations Rosswog 2015, MNRAS 448:3628, §2.3): the
// symmetric form of Vukčević 2012, eq 117 with grad_i W_ij(h_i) -> A_ij = C_i (x_j - x_i) W_ij and
// grad_i W_ij(h_j) -> C_j (x_j - x_i) W_ij (physics/integral_approach_matrix.hpp):
//   dv_i/dt = -sum_j m_j (p_i/rho_i^2 C_i W_ij(h_i) + p_j/rho_j^2 C_j W_ij(h_j)) (x_j - x_i)
//           =  sum_j m_j (p_i/rho_i^2 C_i W_ij(h_i) + p_j/rho_j^2 C_j W_ij(h_j)) dx_ij
// (W_ij(h) the kernel at that particle's h, physics/integral_approach_matrix.hpp, "Which h").
// The pair's term seen from j is the same vector with the opposite sign (dx_ji = -dx_ij, the two
// matrices swap places): m_i dv_i + m_j dv_j = 0 pair by pair, so momentum is conserved on any
// particle set; the energy equation that goes with it is physics/energy_equation_ia.hpp.
#include <memory>

#include "sphmol/physics/integral_approach_matrix.hpp"

namespace sphmol {

template <int D>
class PressureGradientIA final : public PairTermFor<D, PressureGradientIA<D>> {
 public:
  explicit PressureGradientIA(std::shared_ptr<const IntegralApproachField<D>> C) : C_(std::move(C)) {}
  std::string_view name() const override { return "pressure_gradient_integral_approach"; }
  bool zero_beyond_support() const override { return C_->kernel == nullptr; }  // W(r, h_i) may reach past kappa h_ij
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    const double pi = w.p[i] / (w.rho[i] * w.rho[i]);
    double a[D] = {};
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      double dx[D], ci[D], cj[D], r2 = 0.0, Wi, Wj;
      for (int d = 0; d < D; ++d) {
        dx[d] = r.dx[d][k];
        r2 += dx[d] * dx[d];
      }
      C_->weights(w, i, j, r.W[k], r2, Wi, Wj);
      ia_times<D>(C_->of(i), dx, ci);
      ia_times<D>(C_->of(i, j), dx, cj);
      const double pj = w.p[j] / (w.rho[j] * w.rho[j]);
      for (int d = 0; d < D; ++d) a[d] += m[j] * (pi * Wi * ci[d] + pj * Wj * cj[d]);
    }
    for (int d = 0; d < D; ++d) w.dvdt[d][i] += a[d];
  }

 private:
  std::shared_ptr<const IntegralApproachField<D>> C_;
};

}  // namespace sphmol
