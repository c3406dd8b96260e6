#pragma once
// Laminar viscosity of Morris, Fox & Zhu (1997), J. Comput. Phys. 136:214, their eq. (8):
//   dv_i/dt += sum_j m_j (mu_i + mu_j) / (rho_i rho_j) * (x_ij . grad_i W_ij) / (r_ij^2 + eta^2) * v_ij
// with eta^2 = 0.01 h^2 guarding r -> 0. Here x_ij . grad_i W_ij = F_ij r_ij^2. No dimension enters:
// the kernel's second moment, int r^2 W'(r)/r n n dV = -I, is the same in 1, 2 and 3D, so the sum is
// nu laplacian(v) in each. Fluid-wall velocity
// differences are scaled by the wall model's factor (rhs/workspace.hpp, vfac), and a wall particle's
// velocity is the wall model's no-slip velocity where it sets one (v_viscous).
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

template <int D>
class MorrisViscosity final : public PairTermFor<D, MorrisViscosity<D>> {
 public:
  explicit MorrisViscosity(double dynamic_viscosity) : mu_(dynamic_viscosity) {}
  std::string_view name() const override { return "morris_viscosity"; }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    const double eta2 = 0.01 * w.h * w.h;
    const double* vj[D];  // the wall model's no-slip wall velocities, if it sets them (rhs/workspace.hpp)
    for (int d = 0; d < D; ++d) vj[d] = w.v_viscous[d].empty() ? w.v[d].data() : w.v_viscous[d].data();
    double a[D] = {};
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      double r2 = 0.0;
      for (int d = 0; d < D; ++d) {
        const double dx = r.dx[d][k];
        r2 += dx * dx;
      }
      const double s = m[j] * 2.0 * mu_ / (w.rho[i] * w.rho[j]) * r.F[k] * r2 / (r2 + eta2);
      for (int d = 0; d < D; ++d) a[d] += s * r.vfac[k] * (w.v[d][i] - vj[d][j]);
    }
    for (int d = 0; d < D; ++d) w.dvdt[d][i] += a[d];
  }

 private:
  double mu_;
};

}  // namespace sphmol
