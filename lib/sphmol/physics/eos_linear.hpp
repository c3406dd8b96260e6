#pragma once
// Equation of state p = c^2 rho (Morris et al. 1997; Vukčević et al. 2012, eq 20, Vukčević 2012, eq
// 126): an artificially compressible fluid whose sound speed c is chosen so that density varies ~1
// %. With `relative`, p = c^2 (rho - rho0): the same pressure gradient in the continuum, but
// without the background pressure c^2 rho0, which the symmetric SPH gradient (Vukčević 2012, eq
// 117) turns into a spurious force wherever the particle arrangement is not symmetric (e.g. fluid
// rows sliding over a wall). Relative, fluids of several rest densities (Particles::rest_density)
// take p = c^2 (rho - rho0_i), each phase at p = 0 at its own rest density (Colagrossi & Landrini 2003).
#include <algorithm>
#include <cmath>

#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class LinearEos final : public Term<D> {
 public:
  LinearEos(double sound_speed, double rest_density, bool relative)
      : c2_(sound_speed * sound_speed), rho_ref_(relative ? rest_density : 0.0), relative_(relative) {}
  std::string_view name() const override { return relative_ ? "eos_linear_relative" : "eos_linear"; }
  bool runs_in_team() const override { return true; }  // one worksharing loop (Term::runs_in_team)
  void apply(Workspace<D>& w) const override {
    // The particles' own rest densities (Particles::rest_density) for [0, n_own); the rest keep rho0.
    const double* own = relative_ && w.particles ? w.particles->rest_density.data() : nullptr;
    const std::size_t n_own = own ? std::min(w.particles->rest_density.size(), w.n) : 0;
    const double c = std::sqrt(c2_);  // constant sound speed, for the artificial viscosity
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < w.n; ++i) {
      w.p[i] = c2_ * (w.rho[i] - (i < n_own ? own[i] : rho_ref_));
      w.c[i] = c;
    }
  }

 private:
  double c2_, rho_ref_;
  bool relative_;
};

}  // namespace sphmol
