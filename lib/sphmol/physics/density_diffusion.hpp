#pragma once
// delta-SPH density diffusion (Molteni & Colagrossi 2009, Comput. Phys. Commun. 180:861), beyond the
// seeds: a diffusive term added to the continuity equation (Niedoba 2012, eq 2.61) that damps the
// high-frequency pressure noise of weakly compressible SPH,
//   drho_i/dt += delta h c0 sum_j psi_ij . grad_i W_ij m_j / rho_j,
//   psi_ij = 2 (rho_j - rho_i) (x_j - x_i) / |x_ij|^2.
// With grad_i W_ij = F_ij (x_i - x_j) (rhs/workspace.hpp) the dot product is 2 (rho_i - rho_j) F_ij.
// Applied between fluid particles only, as DualSPHysics does: dynamic wall particles carry the
// hydrostatic density of the fluid they hold up, not a diffusing field of their own.
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

}  // namespace sphmol
