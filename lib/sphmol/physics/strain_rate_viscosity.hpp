#pragma once
// Viscous part of the symmetric momentum equation, Vukčević 2012, eq 117 (Vukčević et al. 2012, eq
// 12):
//   dv_a(i)/dt += sum_j m_j (mu eps_ab(i)/rho_i^2 + mu eps_ab(j)/rho_j^2) dW_ij/dx_b(i)
// with the strain rate of physics/strain_rate.hpp and mu = rho0 nu the fluid's dynamic viscosity.
#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class StrainRateViscosity117 final : public Term<D> {
 public:
  explicit StrainRateViscosity117(double dynamic_viscosity) : mu_(dynamic_viscosity) {}
  std::string_view name() const override { return "strain_rate_viscosity_117"; }
  bool reads_stored_pairs() const override { return true; }
  void apply(Workspace<D>& w) const override {
    const auto& P = w.pairs;
    const auto& m = w.particles->mass;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < w.n_fluid; ++i) {
      const double ci = mu_ / (w.rho[i] * w.rho[i]);
      double a[D] = {};
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
        const std::uint32_t j = P.j[k];
        const double cj = mu_ / (w.rho[j] * w.rho[j]);
        double dx[D];
        for (int d = 0; d < D; ++d) dx[d] = w.dx[d][k];
        const double s = m[j] * w.F[k];
        for (int p = 0; p < D; ++p) {
          double t = 0.0;
          for (int q = 0; q < D; ++q) t += (ci * w.strain[p * D + q][i] + cj * w.strain[p * D + q][j]) * dx[q];
          a[p] += s * t;
        }
      }
      for (int d = 0; d < D; ++d) w.dvdt[d][i] += a[d];
    }
  }

 private:
  double mu_;
};

}  // namespace sphmol
