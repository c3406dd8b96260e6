#pragma once
// delta-SPH density diffusion (Molteni & Colagrossi 2009, Comput. Phys. Commun. 180:861), beyond the
// seeds: a diffusive term added to the continuity equation (Niedoba 2012, eq 2.61) that damps the
// high-frequency pressure noise of weakly compressible SPH,
//   drho_i/dt += delta h c0 sum_j psi_ij . grad_i W_ij m_j / rho_j,
//   psi_ij = 2 (rho_j - rho_i) (x_j - x_i) / |x_ij|^2.
// With grad_i W_ij = F_ij (x_i - x_j) (rhs/workspace.hpp) the dot product is 2 (rho_i - rho_j) F_ij.
// Applied between fluid particles only, as DualSPHysics does: dynamic wall particles carry the
// hydrostatic density of the fluid they hold up, not a diffusing field of their own.
//
// The hydrostatic form diffuses only the density's departure from hydrostatics (the dynamic density of
// Fourtakas et al. 2019): a column at rest has dp = rho g . dx, so dRho = (rho / c^2) g . dx, and
// the pair's difference rho_i - rho_j becomes rho_i - rho_j - kbar_ij g(t) . (x_i - x_j), kbar_ij the
// mean of rho / c^2 over the pair (the local EOS slope, exact for any EOS to second order in the pair's
// height difference). The plain form diffuses the hydrostatic density itself wherever a row lacks
// neighbours (the surface, the rows next to the walls, which it does not diffuse across), and a
// column at rest loses its pressure gradient there.
#include <array>
#include <vector>

#include "sphmol/physics/body_force.hpp"
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

// One pair's share of the sum below, before the factor delta h c0; vj = m_j / rho_j, 0 for walls.
inline double density_diffusion_pair(double ri, double rj, double F, double vj) { return 2.0 * (ri - rj) * F * vj; }

template <int D>
class DensityDiffusion final : public PairTermFor<D, DensityDiffusion<D>> {
 public:
  DensityDiffusion(double delta, double h, double sound_speed) : coef_(delta * h * sound_speed) {}
  std::string_view name() const override { return "density_diffusion_molteni_colagrossi"; }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    const std::size_t nf = w.n_fluid;
    double s = 0.0;
    const double ri = w.rho[i];
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      // Fluid neighbours only: a select on the particle index, not a configuration branch.
      const double vj = j < nf ? m[j] / w.rho[j] : 0.0;
      s += density_diffusion_pair(ri, w.rho[j], r.F[k], vj);
    }
    w.drhodt[i] += coef_ * s;
  }

 private:
  double coef_;
};

// The hydrostatic form (above): the body force g with its ramp, as the body-force term applies it.
template <int D>
class HydrostaticDensityDiffusion final : public PairTermFor<D, HydrostaticDensityDiffusion<D>> {
 public:
  HydrostaticDensityDiffusion(double delta, double h, double sound_speed, const std::array<double, D>& g, double ramp)
      : coef_(delta * h * sound_speed), g_(g), ramp_(ramp) {}
  std::string_view name() const override { return "density_diffusion_hydrostatic"; }
  // rho / c^2 and the volume m / rho (0 for walls: fluid pairs only) of every particle once per
  // evaluation, not divisions per pair; shared by the team's threads (ends with the loop's barrier).
  bool prepares_in_team() const override { return true; }
  void prepare(Workspace<D>& w) const override {
#pragma omp single
    {
      kappa_.resize(w.n);
      vol_.resize(w.n);
    }
    const auto& m = w.particles->mass;
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < w.n; ++i) {
      kappa_[i] = w.c[i] > 0.0 ? w.rho[i] / (w.c[i] * w.c[i]) : 0.0;
      vol_[i] = i < w.n_fluid ? m[i] / w.rho[i] : 0.0;
    }
  }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const double f = body_force_ramp_factor(w.t, ramp_);
    std::array<double, D> g{};
    for (int d = 0; d < D; ++d) g[d] = 0.5 * f * g_[d];  // the half of the pair mean folded in
    const double ri = w.rho[i], ki = kappa_[i];
    double s = 0.0;
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      double gx = 0.0;
      for (int d = 0; d < D; ++d) gx += g[d] * r.dx[d][k];
      // rho_i - rho_j less the hydrostatic difference (kappa_i + kappa_j) / 2 g . (x_i - x_j).
      s += density_diffusion_pair(ri - (ki + kappa_[j]) * gx, w.rho[j], r.F[k], vol_[j]);
    }
    w.drhodt[i] += coef_ * s;
  }

 private:
  double coef_;
  std::array<double, D> g_;
  double ramp_;
  mutable std::vector<double> kappa_, vol_;
};

}  // namespace sphmol
