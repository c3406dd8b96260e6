#pragma once
// Laminar viscosity of Morris, Fox & Zhu (1997), J. Comput. Phys. 136:214, their eq. (8):
//   dv_i/dt += sum_j m_j (mu_i + mu_j) / (rho_i rho_j) * (x_ij . grad_i W_ij) / (r_ij^2 + eta^2) * v_ij
// with eta^2 = 0.01 h^2 guarding r -> 0. Here x_ij . grad_i W_ij = F_ij r_ij^2. No dimension enters
// in the continuum: the kernel's second moment, int r^2 W'(r)/r n n dV = -I, is the same in 1, 2 and
// 3D, so the sum is nu laplacian(v) in each. Fluid-wall velocity differences are scaled by the wall
// model's factor (rhs/workspace.hpp, vfac), and a wall particle's velocity is the wall model's
// no-slip velocity where it sets one (v_viscous).
//
// On particles the second moment is a sum, and with eta it is not -I: on a cubic lattice with the cubic
// spline at h = 1.3 dx it is 0.985 I in 3D (0.9998 I in 2D), a viscosity 1.5 % low at every resolution
// (the square duct ran 1.3 % fast at 16, 24 and 32 particles across); with Wendland C2 at h = 2 dx it is
// 0.985 I in 2D. `moment` (LaplacianCorrection::moment) divides each row by its own discrete moment,
//   M_i = -(1/D) sum_j (m_j / rho_j) F_ij r_ij^2 * r_ij^2 / (r_ij^2 + eta^2),
// which makes the sum exact for quadratic fields wherever the support is full and isotropic: the
// scalar normalisation of the corrective smoothed particle method's second derivative (Chen, Beraun &
// Carney 1999; compared with other corrections by Korzilius et al. 2017) applied to Morris' form.
// M_i uses the geometric volumes of wall particles too (the extrapolation factor is a velocity model,
// not quadrature). Rows of unequal M_i exchange unequal forces, so momentum is conserved only to the
// moment's variation (exactly on a lattice).
//
// `moment_symmetric` scales each fluid pair by the mean of the two particles' moments instead,
//   dv_i/dt += sum_j c_ij v_ij * 2 / (M_i + M_j)   (fluid j),   c_ij v_ij / M_i   (wall j),
// with c_ij the Morris coefficient above and M from physics/morris_moment.hpp. The factor is symmetric
// in i and j and so is m_i c_ij = m_i m_j (mu_i + mu_j) / (rho_i rho_j) F_ij ..., so fluid pairs exchange
// equal and opposite forces: linear momentum is conserved to round-off on any particle set. Where M is
// uniform (a lattice, away from walls and surfaces) 2 / (M_i + M_j) = 1 / M_i and the sum is exact for
// quadratic fields like `moment`. Where M varies, expanding 2 / (M_i + M_j) = (1 / M_i)(1 - (M_j - M_i) /
// (2 M_i) + ...) with M_i - M_j ~ x_ij . grad M, v_ij ~ (x_ij . grad) v and sum_j V_j F_ij x_ij x_ij ~ -I,
// the pair form is the row form minus nu (grad M . grad) v / M^2: small where the support is full (M
// varies with the disorder only), large where M changes within a kernel radius (a free surface, walls
// that do not fill the support). Wall pairs keep the row's own 1 / M_i (wall particles have no moment
// and receive no force). The recorded IMEX operator keeps the symmetry m_i L_ij = m_j L_ji of the
// uncorrected one (L itself for equal masses), so conjugate gradients stay applicable.
//
// `Variable`: fluids of several viscosities (a scene's fluid bodies with their own
// kinematic_viscosity or rest density, Particles::viscosity), eq. (8) with each pair's mu from its two
// particles' (pair_mu below): symmetric in i and j, so pairs still exchange equal and opposite forces.
// A wall particle takes the fluid particle's mu (the stress at a wall is that of the fluid beside it).
#include <memory>
#include <stdexcept>

#include "sphmol/physics/morris_moment.hpp"
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

// discretization.laplacian_correction: none, moment (each row by its own M_i), moment_symmetric (each
// pair by 2 / (M_i + M_j)).
enum class LaplacianCorrection { none, moment, moment_symmetric };

template <int D, LaplacianCorrection C = LaplacianCorrection::none, bool Variable = false>
class MorrisViscosity final : public PairTermFor<D, MorrisViscosity<D, C, Variable>> {
  static constexpr bool Normalised = C == LaplacianCorrection::moment;
  static constexpr bool Symmetric = C == LaplacianCorrection::moment_symmetric;

 public:
  // `moment`: the field MorrisMoment writes earlier in the same evaluation (moment_symmetric only).
  explicit MorrisViscosity(double dynamic_viscosity, std::shared_ptr<const MorrisMomentField> moment = nullptr)
      : mu_(dynamic_viscosity), moment_(std::move(moment)) {
    if (Symmetric && !moment_) throw std::invalid_argument("MorrisViscosity: moment_symmetric needs the moment field");
  }
  std::string_view name() const override {
    return Normalised ? "morris_viscosity_normalised" : Symmetric ? "morris_viscosity_moment_symmetric" : "morris_viscosity";
  }
  // Linear in the fluid velocities at fixed positions: the implicit part of an IMEX split.
  bool implicit() const override { return true; }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    if (w.implicit) return record_row(w, i, r);
    const auto& m = w.particles->mass;
    const double eta2 = 0.01 * w.h * w.h;
    const double* vj[D];  // the wall model's no-slip wall velocities, if it sets them (rhs/workspace.hpp)
    for (int d = 0; d < D; ++d) vj[d] = w.v_viscous[d].empty() ? w.v[d].data() : w.v_viscous[d].data();
    double a[D] = {};
    double moment = 0.0;  // sum_j V_j F_ij r^4 / (r^2 + eta^2), negative
    // Fluid pairs [0, nf), then wall pairs [nf, n) (rows are sorted, pair_row.hpp): moment_symmetric's
    // factor is 2 / (M_i + M_j) on the first, 1 / M_i on the second (a select on k, not on the scene).
    const std::uint32_t nf = Symmetric ? r.first_wall(w.n_fluid) : r.n;
    const double* M = Symmetric ? moment_->data() : nullptr;
    const double Mi = Symmetric ? M[i] : 1.0;
    [[maybe_unused]] const double* mu = Variable ? w.particles->viscosity.data() : nullptr;
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      double r2 = 0.0;
      for (int d = 0; d < D; ++d) {
        const double dx = r.dx[d][k];
        r2 += dx * dx;
      }
      const double g = r.F[k] * r2 / (r2 + eta2);
      double s = m[j] * pair_mu(mu, w.n_fluid, i, j) / (w.rho[i] * w.rho[j]) * g;
      if constexpr (Symmetric) s *= k < nf ? 2.0 / (Mi + M[j]) : 1.0 / Mi;
      for (int d = 0; d < D; ++d) a[d] += s * r.vfac[k] * (w.v[d][i] - vj[d][j]);
      if constexpr (Normalised) moment += m[j] / w.rho[j] * g * r2;
    }
    double scale = 1.0;
    if constexpr (Normalised) {
      // A particle with no neighbours has no Laplacian to correct.
      if (moment < 0.0) scale = -static_cast<double>(D) / moment;
    }
    for (int d = 0; d < D; ++d) w.dvdt[d][i] += scale * a[d];
  }

 private:
  // The same sum as row_impl written as a row of L v + b (time/viscous_operator.hpp): c_ij on the
  // diagonal and against each fluid neighbour, the wall velocities into b. The wall model's no-slip
  // velocities (v_viscous) depend on the fluid velocities and are refused with IMEX integrators
  // (config/loader.cpp), so wall velocities here are the prescribed ones.
  void record_row(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    ViscousOperator& op = *w.implicit;
    const auto& m = w.particles->mass;
    const double eta2 = 0.01 * w.h * w.h;
    std::uint32_t* col = op.columns();
    double* coef = op.coefficients();
    const std::uint32_t first = op.first(i);
    std::uint32_t count = 0;
    double diag = 0.0, b[D] = {}, moment = 0.0;
    const std::uint32_t nf = Symmetric ? r.first_wall(w.n_fluid) : r.n;
    const double* M = Symmetric ? moment_->data() : nullptr;
    const double Mi = Symmetric ? M[i] : 1.0;
    [[maybe_unused]] const double* mu = Variable ? w.particles->viscosity.data() : nullptr;
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      double r2 = 0.0;
      for (int d = 0; d < D; ++d) r2 += r.dx[d][k] * r.dx[d][k];
      const double g = r.F[k] * r2 / (r2 + eta2);
      double c = m[j] * pair_mu(mu, w.n_fluid, i, j) / (w.rho[i] * w.rho[j]) * g * r.vfac[k];
      if constexpr (Symmetric) c *= k < nf ? 2.0 / (Mi + M[j]) : 1.0 / Mi;
      diag += c;
      if (j < w.n_fluid) {
        col[first + count] = w.order ? w.order[j] : j;
        coef[first + count] = c;
        ++count;
      } else {
        for (int d = 0; d < D; ++d) b[d] -= c * w.v[d][j];
      }
      if constexpr (Normalised) moment += m[j] / w.rho[j] * g * r2;
    }
    double scale = 1.0;
    if constexpr (Normalised) {
      if (moment < 0.0) scale = -static_cast<double>(D) / moment;
      for (std::uint32_t k = 0; k < count; ++k) coef[first + k] *= scale;
      for (int d = 0; d < D; ++d) b[d] *= scale;
    }
    op.finish_row(i, count, scale * diag, b);
  }

  // mu_i + mu_j of Morris et al. (1997) eq. (8): 2 mu for one fluid. Across fluids of different mu,
  // twice their harmonic mean 4 mu_i mu_j / (mu_i + mu_j) (Cleary 1998), as for the heat flux across
  // materials of different conductivity (Cleary & Monaghan 1999): the shear stress is then continuous
  // across the interface; the arithmetic mean smears the jump over the kernel and gave a two-layer
  // Couette flow 2 % of the wall speed off. A wall (j >= n_fluid, ghost images included, which have
  // no entry) takes mu_i.
  double pair_mu([[maybe_unused]] const double* mu, [[maybe_unused]] std::size_t n_fluid, [[maybe_unused]] std::size_t i,
                 [[maybe_unused]] std::size_t j) const {
    if constexpr (Variable) {
      const double a = mu[i], b = j < n_fluid ? mu[j] : mu[i];
      return a == b ? 2.0 * a : a + b > 0.0 ? 4.0 * a * b / (a + b) : 0.0;
    } else {
      return 2.0 * mu_;
    }
  }

  double mu_;
  std::shared_ptr<const MorrisMomentField> moment_;  // moment_symmetric only
};

}  // namespace sphmol
