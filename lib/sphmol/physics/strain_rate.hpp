#pragma once
// Strain-rate tensor from velocity differences, Vukčević 2012, eq 122 / Vukčević et al. 2012, eq
// 13:
//   eps_ab(i) = sum_j V_j [ v_b(ji) dW/dx_a + v_a(ji) dW/dx_b ] - 2/3 delta_ab sum_j V_j v_c(ji) dW/dx_c
// with V_j = m_j / rho_j and v(ji) = v_j - v_i. Computed for wall rows too, because the momentum
// equation (Vukčević 2012, eq 117) needs eps at the wall neighbours; wall rows see only fluid
// particles, and a missing wall-wall pair contributes nothing for walls that move together.
// Velocity differences of fluid-wall pairs are scaled by the wall model's factor
// (rhs/workspace.hpp, vfac), and taken from the viscous velocities where a wall treatment sets them
// (Workspace::v_viscous: no-slip ghost images), since the strain rate feeds the viscous stress only.
// The 2/3 is Stokes' hypothesis for the fluid, not the dimension of the scene: eps is traceless in 3D,
// and in 2D (1D) it is the in-plane (axial) deviatoric strain of a plane (one-dimensional) flow of
// the same fluid, so the term holds in every dimension.
#include <Eigen/Dense>

#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class StrainRate final : public Term<D> {
 public:
  std::string_view name() const override { return "strain_rate"; }
  bool reads_stored_pairs() const override { return true; }
  void apply(Workspace<D>& w) const override {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < w.n_fluid; ++i) {
      double g[D][D];
      gradient_sums(w, i, g, nullptr);
      store(w, i, g);
    }
    // Wall rows list only fluid neighbours: their support is cut in half. The velocities they see are
    // the wall model's (for the Morris model, a linear continuation of the fluid profile), so a
    // first-order correction g <- M^-1 g with M_ac = -sum_j V_j F_ij dx_a dx_c recovers the gradient
    // of a linear field exactly from the half support.
#pragma omp parallel for schedule(static)
    for (std::size_t i = w.n_fluid; i < w.n; ++i) {
      double g[D][D], M[D][D];
      gradient_sums(w, i, g, M);
      Eigen::Matrix<double, D, D> Mm, G;
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) {
          Mm(a, b) = M[a][b];
          G(a, b) = g[a][b];
        }
      const auto lu = Mm.fullPivLu();
      if (lu.isInvertible()) {
        G = lu.solve(G).eval();
        for (int a = 0; a < D; ++a)
          for (int b = 0; b < D; ++b) g[a][b] = G(a, b);
      }
      store(w, i, g);
    }
  }

 private:
  // g[a][b] = sum_j V_j dv_b dW/dx_a with dv = vfac (v_j - v_i); M (if wanted) = -sum_j V_j F dx dx^T.
  static void gradient_sums(const Workspace<D>& w, std::size_t i, double (&g)[D][D], double (*M)[D]) {
    const auto& P = w.pairs;
    const auto& m = w.particles->mass;
    const double* v[D];
    for (int d = 0; d < D; ++d) v[d] = w.v_viscous[d].empty() ? w.v[d].data() : w.v_viscous[d].data();
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) {
        g[a][b] = 0.0;
        if (M) M[a][b] = 0.0;
      }
    for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
      const std::uint32_t j = P.j[k];
      const double s = m[j] / w.rho[j] * w.F[k];
      double dx[D], dv[D];
      for (int d = 0; d < D; ++d) {
        dx[d] = w.dx[d][k];
        dv[d] = w.vfac[k] * (v[d][j] - v[d][i]);
      }
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) {
          g[a][b] += s * dv[b] * dx[a];
          if (M) M[a][b] -= s * dx[a] * dx[b];
        }
    }
  }
  static void store(Workspace<D>& w, std::size_t i, const double (&g)[D][D]) {
    double div = 0.0;
    for (int a = 0; a < D; ++a) div += g[a][a];
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) w.strain[a * D + b][i] = g[a][b] + g[b][a] - (a == b ? 2.0 / 3.0 * div : 0.0);
  }
};

}  // namespace sphmol
