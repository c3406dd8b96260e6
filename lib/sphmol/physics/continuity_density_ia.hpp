#pragma once
// Continuity density with the integral approach's gradients (physics/integral_approach_matrix.hpp):
//   drho_i/dt = -rho_i div v_i,   div v_i = sum_j V_j (v_j - v_i) . A_ij,   A_ij = -C_i dx_ij W_ij,
// (W_ij at h_i, physics/integral_approach_matrix.hpp, "Which h") with the weights of
// physics/continuity_density.hpp: Volume (Colagrossi & Landrini 2003)
//   drho_i/dt = -rho_i sum_j (m_j / rho_j) W_ij v_ij . (C_i dx_ij),
// or mass weights (Niedoba 2012, eq 2.61 with grad_i W_ij -> A_ij)
//   drho_i/dt = -sum_j m_j W_ij v_ij . (C_i dx_ij).
// The volume-weighted divergence is exact for a linear velocity field on any particle set with a full
// neighbourhood, as the IA momentum equation's pressure gradient is for a linear pressure.
#include <memory>

#include "sphmol/physics/integral_approach_matrix.hpp"

namespace sphmol {

template <int D, bool Volume = true>
class ContinuityDensityIA final : public PairTermFor<D, ContinuityDensityIA<D, Volume>> {
 public:
  explicit ContinuityDensityIA(std::shared_ptr<const IntegralApproachField<D>> C) : C_(std::move(C)) {}
  std::string_view name() const override {
    return Volume ? "continuity_density_volume_integral_approach" : "continuity_density_integral_approach";
  }
  bool zero_beyond_support() const override { return C_->kernel == nullptr; }  // W(r, h_i) may reach past kappa h_ij
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    w.drhodt[i] += (Volume ? w.rho[i] : 1.0) * ia_divergence_sum<D, Volume>(w, i, r, *C_);
  }

 private:
  std::shared_ptr<const IntegralApproachField<D>> C_;
};

}  // namespace sphmol
