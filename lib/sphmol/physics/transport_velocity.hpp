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
#include <vector>

#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class TransportVelocity final : public Term<D> {
 public:
  TransportVelocity(double background_pressure, double time_scale, bool extra_stress)
      : pb_(background_pressure), tau_(time_scale), stress_(extra_stress) {}
  std::string_view name() const override { return stress_ ? "transport_velocity+extra_stress" : "transport_velocity"; }
  void apply(Workspace<D>& w) const override {
    const auto& P = w.pairs;
    const auto& m = w.particles->mass;
    const std::size_t nf = w.n_fluid;
    for (auto& d : du_) d.assign(nf, 0.0);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < nf; ++i) {
      const double Vi = m[i] / w.rho[i];
      double s[D] = {};
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
        const std::uint32_t j = P.j[k];
        const double Vj = m[j] / w.rho[j];
        const double f = (Vi * Vi + Vj * Vj) * w.F[k];
        for (int d = 0; d < D; ++d) s[d] += f * w.dx[d][k];
      }
      const double c = -tau_ * pb_ / m[i];
      for (int d = 0; d < D; ++d) {
        du_[d][i] = c * s[d];
        w.dxdt[d][i] += du_[d][i];
      }
    }
    if (!stress_) return;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < nf; ++i) {
      const double Vi = m[i] / w.rho[i];
      double a[D] = {};
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
        const std::uint32_t j = P.j[k];
        const double Vj = m[j] / w.rho[j];
        const double f = 0.5 * (Vi * Vi + Vj * Vj) * w.F[k];
        // (A_i + A_j) . dx, A_ab = rho v_a du_b; walls (j >= n_fluid) carry no extra stress
        double Ag[D];
        for (int d = 0; d < D; ++d) {
          double dui = 0.0;
          for (int e = 0; e < D; ++e) dui += du_[e][i] * w.dx[e][k];
          Ag[d] = w.rho[i] * w.v[d][i] * dui;
        }
        if (j < nf) {
          double duj = 0.0;
          for (int e = 0; e < D; ++e) duj += du_[e][j] * w.dx[e][k];
          for (int d = 0; d < D; ++d) Ag[d] += w.rho[j] * w.v[d][j] * duj;
        }
        for (int d = 0; d < D; ++d) a[d] += f * Ag[d];
      }
      for (int d = 0; d < D; ++d) w.dvdt[d][i] += a[d] / m[i];
    }
  }

 private:
  double pb_, tau_;
  bool stress_;
  mutable std::array<std::vector<double>, D> du_;  // per fluid particle, shared by the two passes
};

}  // namespace sphmol
