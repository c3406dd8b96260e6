#pragma once
// The weakly compressible fluid row of the dam break and every continuity-density scene without a
// physical viscosity: continuity density (seed 003 eq 2.61), delta-SPH diffusion (optional), and the
// momentum equation with Monaghan's artificial viscosity inside the pressure bracket (seed 003 eq 2.71:
// dv_i/dt = -sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2 + Pi_ij) grad_i W_ij, pressure as seed 000 eq 117),
// in one sum over the row: each pair's neighbour data (v_j, rho_j, c_j, m_j) are loaded once,
// v_ij . x_ij is formed once, and p/rho^2 and m/rho are computed once per particle, not per pair,
// leaving one division per pair (in Pi_ij). The per-pair formulas are the separate terms' (continuity_rate,
// density_diffusion_pair, MonaghanPi); only the summation order differs from running them apart
// (round-off; tests/integration/test_fused_pair_passes.cpp). Chosen by the assembly when exactly
// these terms meet (discretization.combine_terms).
#include <vector>

#include "sphmol/physics/artificial_viscosity.hpp"
#include "sphmol/physics/density_diffusion.hpp"
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

template <int D, bool WithDiffusion>
class WeaklyCompressibleRow final : public PairTermFor<D, WeaklyCompressibleRow<D, WithDiffusion>> {
 public:
  WeaklyCompressibleRow(double diffusion_coefficient, MonaghanPi pi) : diff_(diffusion_coefficient), pi_(pi) {}
  std::string_view name() const override {
    return WithDiffusion ? "continuity_density+density_diffusion_molteni_colagrossi+pressure_gradient_117+artificial_viscosity"
                         : "continuity_density+pressure_gradient_117+artificial_viscosity";
  }
  void prepare(Workspace<D>& w) const override {
    q_.resize(w.n);
    if constexpr (WithDiffusion) vol_.resize(w.n);
    const auto& m = w.particles->mass;
    const std::size_t nf = w.n_fluid;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < w.n; ++i) {
      q_[i] = w.p[i] / (w.rho[i] * w.rho[i]);
      if constexpr (WithDiffusion) vol_[i] = i < nf ? m[i] / w.rho[i] : 0.0;  // delta-SPH: fluid neighbours only
    }
  }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    const double* q = q_.data();
    const double* vol = vol_.data();
    const double ri = w.rho[i], qi = q[i], hi = w.hs[i], ci = w.c[i];
    double vi[D];
    for (int d = 0; d < D; ++d) vi[d] = w.v[d][i];
    double cont = 0.0, diff = 0.0, a[D] = {};
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      const double mj = m[j], rj = w.rho[j], F = r.F[k];
      double vx = 0.0, r2 = 0.0;
      for (int d = 0; d < D; ++d) {
        vx += (vi[d] - w.v[d][j]) * r.dx[d][k];
        r2 += r.dx[d][k] * r.dx[d][k];
      }
      cont += mj * vx * F;
      if constexpr (WithDiffusion) diff += density_diffusion_pair(ri, rj, F, vol[j]);
      const double pij = pi_(vx, r2, 0.5 * (hi + w.hs[j]), 0.5 * (ci + w.c[j]), 0.5 * (ri + rj));
      const double s = mj * (qi + q[j] + pij) * F;
      for (int d = 0; d < D; ++d) a[d] -= s * r.dx[d][k];
    }
    w.drhodt[i] += cont;
    if constexpr (WithDiffusion) w.drhodt[i] += diff_ * diff;
    for (int d = 0; d < D; ++d) w.dvdt[d][i] += a[d];
  }

 private:
  double diff_;  // delta h c0
  MonaghanPi pi_;
  mutable std::vector<double> q_, vol_;  // p / rho^2 and (fluid) m / rho per particle, this evaluation
};

}  // namespace sphmol
