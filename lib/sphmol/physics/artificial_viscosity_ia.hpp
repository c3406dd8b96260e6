#pragma once
// Artificial viscosity with the integral approach's gradients: Pi_ij of physics/artificial_viscosity.hpp
// (either form, with its switch) and grad_i W_ij replaced by the mean of the pair's two IA vectors
// (Rosswog 2015, MNRAS 448:3628, §2.3),
//   Abar_ij = (A_ij(C_i) + A_ij(C_j)) / 2 = -(W_ij(h_i) C_i + W_ij(h_j) C_j) dx_ij / 2,
//   dv_i/dt -= sum_j m_j Pi_ij Abar_ij,   de_i/dt += 1/2 sum_j m_j Pi_ij v_ij . Abar_ij.
// Abar_ji = -Abar_ij and Pi_ij = Pi_ji: the pair forces are equal and opposite and their work goes
// into the two particles' energies in halves, as in the standard form.
#include <memory>
#include <type_traits>

#include "sphmol/physics/artificial_viscosity.hpp"
#include "sphmol/physics/integral_approach_matrix.hpp"

namespace sphmol {

template <int D, bool WithEnergy, class Pi = MonaghanPi>
class ArtificialViscosityIA final : public PairTermFor<D, ArtificialViscosityIA<D, WithEnergy, Pi>> {
 public:
  ArtificialViscosityIA(Pi pi, std::shared_ptr<const IntegralApproachField<D>> C) : pi_(pi), C_(std::move(C)) {}
  std::string_view name() const override {
    if constexpr (std::is_same_v<Pi, SignalVelocityPi>)
      return WithEnergy ? "artificial_viscosity_signal_velocity_integral_approach+heating"
                        : "artificial_viscosity_signal_velocity_integral_approach";
    return WithEnergy ? "artificial_viscosity_integral_approach+heating" : "artificial_viscosity_integral_approach";
  }
  bool zero_beyond_support() const override { return C_->kernel == nullptr; }  // W(r, h_i) may reach past kappa h_ij
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
        double a[D] = {}, de = 0.0;
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      double dx[D], ci[D], cj[D], vx = 0.0, r2 = 0.0;
      for (int d = 0; d < D; ++d) {
        dx[d] = r.dx[d][k];
        vx += (w.v[d][i] - w.v[d][j]) * dx[d];
        r2 += dx[d] * dx[d];
      }
      double Wi, Wj;
      C_->weights(w, i, j, r.W[k], r2, Wi, Wj);
      ia_times<D>(C_->of(i), dx, ci);
      ia_times<D>(C_->of(i, j), dx, cj);
      const double pi = pi_(vx, r2, 0.5 * (w.hs[i] + w.hs[j]), 0.5 * (w.c[i] + w.c[j]), 0.5 * (w.rho[i] + w.rho[j]));
      const double s = 0.5 * m[j] * pi;  // -m_j Pi_ij Abar_ij = s (W_i C_i + W_j C_j) dx
      double vA = 0.0;                   // v_ij . (W_i C_i + W_j C_j) dx
      for (int d = 0; d < D; ++d) {
        const double g = Wi * ci[d] + Wj * cj[d];
        a[d] += s * g;
        vA += (w.v[d][i] - w.v[d][j]) * g;
      }
      if constexpr (WithEnergy) de -= 0.5 * s * vA;
    }
    for (int d = 0; d < D; ++d) w.dvdt[d][i] += a[d];
    if constexpr (WithEnergy) w.dedt[i] += de;
  }

 private:
  Pi pi_;
  std::shared_ptr<const IntegralApproachField<D>> C_;
};

}  // namespace sphmol
