#pragma once
// Energy equation of an inviscid fluid with the integral approach's gradients, the work of
// physics/pressure_gradient_ia.hpp (Rosswog 2015, MNRAS 448:3628, §2.3):
//   de_i/dt = p_i/rho_i^2 sum_j m_j v_ij . A_ij = -p_i/rho_i^2 sum_j m_j W_ij(h_i) v_ij . (C_i dx_ij),
// i.e. p_i/rho_i^2 times the IA estimate of -rho_i div v with mass weights. With the momentum
// equation's pairs, sum_i m_i (de_i/dt + v_i . dv_i/dt) = 0 pair by pair: the pair (i, j) gives
// -m_i m_j W v_ij . (p_i/rho_i^2 C_i + p_j/rho_j^2 C_j) dx_ij to the kinetic energy and the same with
// the opposite sign to the internal energies of i (C_i) and j (C_j). The artificial viscosity adds its
// own work (physics/artificial_viscosity_ia.hpp).
#include <memory>

#include "sphmol/physics/integral_approach_matrix.hpp"

namespace sphmol {

template <int D>
class EnergyEquationIA final : public PairTermFor<D, EnergyEquationIA<D>> {
 public:
  explicit EnergyEquationIA(std::shared_ptr<const IntegralApproachField<D>> C) : C_(std::move(C)) {}
  std::string_view name() const override { return "energy_equation_integral_approach"; }
  bool zero_beyond_support() const override { return C_->kernel == nullptr; }  // W(r, h_i) may reach past kappa h_ij
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    w.dedt[i] += w.p[i] / (w.rho[i] * w.rho[i]) * ia_divergence_sum<D, false>(w, i, r, *C_);
  }

 private:
  std::shared_ptr<const IntegralApproachField<D>> C_;
};

}  // namespace sphmol
