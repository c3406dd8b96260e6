#pragma once
// Transport-velocity formulation of Adami, Hu & Adams (2013), J. Comput. Phys. 241:292, written for the
// method of lines. Particles move with the transport velocity v~ = v + du instead of v:
//   dx_i/dt += du_i,   du_i = -(tau p_b / m_i) sum_j (V_i^2 + V_j^2) grad_i W_ij,   V = m / rho   (their eq. 13)
// a background pressure p_b that acts on the particle positions only, never on the momentum, so it
// keeps the particles evenly spread (no tensile clumping where the gauge pressure is negative, no
// streamline-aligned lattice) without the spurious force a background pressure in the momentum adds.
// Adami et al. take du from one time step (tau = dt); an ODE right-hand side has no step, so tau is a
// fixed time scale, tau = step_factor h / c (default 0.25: their acoustic step), with p_b = rho0 c^2.
// Since v is now carried along v~, the momentum gets the extra stress A = rho v (v~ - v) (their eq. 8/12):
//   dv_i/dt += (1/m_i) sum_j (V_i^2 + V_j^2) (A_i + A_j)/2 . grad_i W_ij,   (A . g)_a = sum_b A_ab g_b,
// optional (`extra_stress`). Wall particles enter the sums with their rest volume and A = 0.
#include <array>
#include <memory>
#include <vector>

#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

// du_i per fluid particle: written by the shift, read at neighbours by the extra stress.
template <int D>
using TransportShiftField = std::array<std::vector<double>, D>;

template <int D>
class TransportVelocityShift final : public PairTermFor<D, TransportVelocityShift<D>> {
 public:
  TransportVelocityShift(double background_pressure, double time_scale, std::shared_ptr<TransportShiftField<D>> du)
      : pb_(background_pressure), tau_(time_scale), du_(std::move(du)) {}
  std::string_view name() const override { return "transport_velocity"; }
  // The extra stress, when on, reads du_j.
  bool feeds_neighbours() const override { return du_ != nullptr; }
  void prepare(Workspace<D>& w) const override {
    if (du_)
      for (auto& d : *du_) d.assign(w.n_fluid, 0.0);
  }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    const double Vi = m[i] / w.rho[i];
    double s[D] = {};
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      const double Vj = m[j] / w.rho[j];
      const double f = (Vi * Vi + Vj * Vj) * r.F[k];
      for (int d = 0; d < D; ++d) s[d] += f * r.dx[d][k];
    }
    const double c = -tau_ * pb_ / m[i];
    for (int d = 0; d < D; ++d) {
      const double du = c * s[d];
      if (du_) (*du_)[d][i] = du;
      w.dxdt[d][i] += du;
    }
  }

 private:
  double pb_, tau_;
  std::shared_ptr<TransportShiftField<D>> du_;  // null without the extra stress
};

template <int D>
class TransportVelocityStress final : public PairTermFor<D, TransportVelocityStress<D>> {
 public:
  explicit TransportVelocityStress(std::shared_ptr<const TransportShiftField<D>> du) : du_(std::move(du)) {}
  std::string_view name() const override { return "transport_velocity_extra_stress"; }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    const auto& du = *du_;
    const std::size_t nf = w.n_fluid;
    const double Vi = m[i] / w.rho[i];
    double a[D] = {};
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      const double Vj = m[j] / w.rho[j];
      const double f = 0.5 * (Vi * Vi + Vj * Vj) * r.F[k];
      // (A_i + A_j) . dx, A_ab = rho v_a du_b; walls (j >= n_fluid) carry no extra stress
      double Ag[D];
      for (int d = 0; d < D; ++d) {
        double dui = 0.0;
        for (int e = 0; e < D; ++e) dui += du[e][i] * r.dx[e][k];
        Ag[d] = w.rho[i] * w.v[d][i] * dui;
      }
      if (j < nf) {
        double duj = 0.0;
        for (int e = 0; e < D; ++e) duj += du[e][j] * r.dx[e][k];
        for (int d = 0; d < D; ++d) Ag[d] += w.rho[j] * w.v[d][j] * duj;
      }
      for (int d = 0; d < D; ++d) a[d] += f * Ag[d];
    }
    for (int d = 0; d < D; ++d) w.dvdt[d][i] += a[d] / m[i];
  }

 private:
  std::shared_ptr<const TransportShiftField<D>> du_;
};

}  // namespace sphmol
