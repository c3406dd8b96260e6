#pragma once
// Bulk viscosity: the viscous stress zeta rho (div v) I of a Newtonian fluid's volume changes (Landau &
// Lifshitz 1987, sec. 15), written as a viscous pressure p_b = -zeta rho div v in the symmetric SPH
// pressure gradient (Monaghan 1992, sec. 3):
//   dv_i/dt += -sum_j m_j (p_b,i / rho_i^2 + p_b,j / rho_j^2) grad_i W_ij
//            =  zeta sum_j m_j (div_i / rho_i + div_j / rho_j) grad_i W_ij,
// with div from physics/velocity_divergence.hpp. In the continuum it is zeta grad(div v): it acts on the
// compressive (acoustic) part of the velocity only and leaves a divergence-free flow alone, so it damps
// the particle-scale sound waves that a weakly compressible model keeps in a vortex (docs/verification.md,
// "Taylor–Green: a bulk viscosity for the acoustic noise") without adding to the shear viscosity. Fluid
// pairs exchange equal and opposite forces (momentum to round-off). A wall neighbour has no viscous
// pressure of its own (p_b,j = 0): the walls' velocities enter the divergence as given values, and the
// force is then the adjoint of the divergence, so the term dissipates exactly
//   sum_i m_i v_i . dv_i/dt = -zeta sum_i m_i div_i^2   (uniform rho, walls included).
// The mirror rule p_b,j = p_b,i of the extrapolated wall pressure counts the wall pairs twice in that
// balance, -zeta sum_i m_i div_i (div_i + div_i^walls), which is not negative: the cavity at 40^2 blew
// up at t = 0.95 s with it (bulk_viscosity 1) and runs to steady state without it.
//
// Being the gradient of a divergence, each a sum over the support, the operator reaches only as high a
// wavenumber as a two-kernel stencil resolves: its largest eigenvalue on a lattice is 0.19-0.20 of the
// Morris Laplacian's (Wendland C2 at h = 1.5-2.5 dx, cubic spline at 1-1.5 dx, 2D and 3D), so the
// explicit step limit counts zeta / 4 with the kinematic viscosity (rhs/sph_system.hpp, cfl_step).
// zeta = discretization.bulk_viscosity x c0 h (config/README.md).
#include <memory>

#include "sphmol/physics/velocity_divergence.hpp"
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

template <int D>
class BulkViscosity final : public PairTermFor<D, BulkViscosity<D>> {
 public:
  BulkViscosity(double zeta, std::shared_ptr<const VelocityDivergenceField> div) : zeta_(zeta), div_(std::move(div)) {}
  std::string_view name() const override { return "bulk_viscosity"; }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    const double* div = div_->data();
    const double qi = div[i] / w.rho[i];
    const std::uint32_t nf = r.first_wall(w.n_fluid);
    double a[D] = {};
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      const double qj = k < nf ? div[j] / w.rho[j] : 0.0;
      const double s = m[j] * (qi + qj) * r.F[k];
      for (int d = 0; d < D; ++d) a[d] += s * r.dx[d][k];
    }
    for (int d = 0; d < D; ++d) w.dvdt[d][i] += zeta_ * a[d];
  }

 private:
  double zeta_;
  std::shared_ptr<const VelocityDivergenceField> div_;
};

}  // namespace sphmol
