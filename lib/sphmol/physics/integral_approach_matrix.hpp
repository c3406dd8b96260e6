#pragma once
// The matrix of the integral approach to derivatives (IA) of Garcia-Senz, Cabezón & Escartín (2012,
// A&A 538:A9, §2), per particle:
//   tau_i = sum_j V_j (x_j - x_i)(x_j - x_i)^T W_ij,   C_i = tau_i^-1,   V_j = m_j / rho_j,
// and the vector that replaces the kernel gradient grad_i W_ij in every IA pair term,
//   A_ij = C_i (x_j - x_i) W_ij = -C_i dx_ij W_ij   (dx_ij = x_i - x_j, rhs/pair_row.hpp).
// By construction sum_j V_j (f_j - f_i) A_ij is the exact gradient of a linear f on any particle set
// with a full (non-degenerate) neighbourhood, where the kernel-gradient sum sum_j V_j (f_j - f_i)
// grad_i W_ij is exact only where the lattice sums reproduce the kernel's integrals (an isotropic,
// regular support). In the continuum tau = (1/D) int r^2 W dV I, and C_i W_ij has the integrals of
// -F_ij (for a Gaussian kernel C W = -F pair by pair), so the IA equations have the standard ones as
// their continuum limit (Garcia-Senz et al. 2012, §2; Rosswog 2015, MNRAS 448:3628, §2.3).
//
// Which h. The matrix and every vector made with it use the kernel at that particle's own h: C_i and
// A_ij(C_i) with W(r, h_i), C_j and A_ij(C_j) with W(r, h_j) (Rosswog 2015: W_ab(h_a), W_ab(h_b)), so
// that int y (x) C(h) y W(y, h) dy = I holds for each vector at its own h. On a smoothly graded lattice
// the pair's W(r, h_ij), h_ij = (h_i + h_j)/2, does about as well (the first-order errors of the two
// pressure terms cancel; tests/unit/test_integral_approach.cpp), but where h changes several-fold
// within a support, as at a shock tube's initial jump (h_right / h_left = 8 in 1D), it does not: the
// 1D Sod fan head came out 8.6 local spacings off with W(r, h_ij) and 0.33 with each particle's h
// (docs/verification.md, "Sod with the integral approach"). With one h both are W_ij. The pairs are
// those of the kernel pass, r < kappa h_ij: where h_i > h_ij, the pairs between kappa h_ij and
// kappa h_i are missing from W(r, h_i); they lie in the kernel's tail (for the Gaussians, inside
// their taper).
//
// The matrices are a pass of their own (each IA row reads C_j of its neighbours, which ends a fused
// pass, rhs/pair_pass_plan.hpp), over fluid rows; ghost images get their source's matrix mirrored
// (boundary/ghost_integral_approach_matrix.hpp), since an image's own row lacks the images of images.
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

// C_i per particle (workspace index), row-major D x D at [i * D * D]: written by IntegralApproachMatrix
// (fluid rows) and the ghost mirror, read at both particles of a pair by the IA terms. Wall particles
// (not ghost images) list only fluid neighbours (neighbors/neighbor_search.hpp), so a sum over their
// own row would see half a support: they carry no matrix, and a pair of fluid row i with such a wall
// particle uses C_i for both (as moment_symmetric's wall pairs keep the row's own moment,
// physics/morris_viscosity.hpp). Wall particles receive no force, so no pair symmetry is lost.
template <int D>
struct IntegralApproachField {
  std::vector<double> C;
  std::size_t wall_begin = 0, wall_end = 0;  // the wall particles without a matrix, [wall_begin, wall_end)
  // With a variable h: W(r, h) of the scene's kernel, for the kernels at each particle's own h. Null:
  // one h, and the pair's W_ij is both.
  double (*kernel)(double r, double h) = nullptr;
  const double* of(std::size_t i) const { return C.data() + i * D * D; }
  bool no_matrix(std::uint32_t j) const { return j >= wall_begin && j < wall_end; }
  // The matrix of j in the pair of row i.
  const double* of(std::size_t i, std::uint32_t j) const { return of(no_matrix(j) ? i : j); }
  // The kernels of the pair (i, j) at h_i and at h_j (W_ij when h is one), r2 = |dx_ij|^2.
  void weights(const Workspace<D>& w, std::size_t i, std::uint32_t j, double Wij, double r2, double& Wi, double& Wj) const {
    if (!kernel) {
      Wi = Wj = Wij;
      return;
    }
    const double r = std::sqrt(r2);
    Wi = kernel(r, w.hs[i]);
    Wj = no_matrix(j) ? Wi : kernel(r, w.hs[j]);
  }
  double own(const Workspace<D>& w, std::size_t i, double Wij, double r2) const {
    return kernel ? kernel(std::sqrt(r2), w.hs[i]) : Wij;
  }
};

// c = C_i dx for the row-major D x D matrix at C (the IA terms' A_ij is -c W_ij).
template <int D>
[[gnu::always_inline]] inline void ia_times(const double* C, const double (&dx)[D], double (&c)[D]) {
  for (int a = 0; a < D; ++a) {
    double s = 0.0;
    for (int b = 0; b < D; ++b) s += C[a * D + b] * dx[b];
    c[a] = s;
  }
}

// C = tau^-1 for the symmetric D x D tau (row-major). A tau that is singular or nearly so (a particle
// whose neighbours lie on a line, or none) gets the isotropic D / trace(tau) I: the inverse of tau's
// isotropic part, which the exact inverse is wherever the support is full and regular.
template <int D>
inline void ia_invert(const double (&tau)[D * D], double* C) {
  Eigen::Matrix<double, D, D> T;
  double trace = 0.0;
  for (int a = 0; a < D; ++a) {
    trace += tau[a * D + a];
    for (int b = 0; b < D; ++b) T(a, b) = tau[a * D + b];
  }
  const double det = T.determinant();
  const double iso = std::pow(trace / D, D);
  if (trace > 0.0 && det > 1e-10 * iso) {
    const Eigen::Matrix<double, D, D> inv = T.inverse();
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) C[a * D + b] = 0.5 * (inv(a, b) + inv(b, a));  // symmetric to round-off
    return;
  }
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) C[a * D + b] = a == b && trace > 0.0 ? D / trace : 0.0;
}

// sum_j w_j v_ij . A_ij = -sum_j w_j W_ij(h_i) v_ij . (C_i dx_ij) over row i, w_j = m_j (Volume = false)
// or m_j / rho_j: the IA estimate of -rho_i div v_i (mass weights) or -div v_i (volume weights), read by
// the continuity and energy equations.
template <int D, bool Volume>
inline double ia_divergence_sum(const Workspace<D>& w, std::size_t i, const PairRow<D>& r, const IntegralApproachField<D>& C) {
  const auto& m = w.particles->mass;
  const double* Ci = C.of(i);
  double s = 0.0;
  for (std::uint32_t k = 0; k < r.n; ++k) {
    const std::uint32_t j = r.j[k];
    double dx[D], ci[D], r2 = 0.0, vc = 0.0;
    for (int d = 0; d < D; ++d) {
      dx[d] = r.dx[d][k];
      r2 += dx[d] * dx[d];
    }
    ia_times<D>(Ci, dx, ci);
    for (int d = 0; d < D; ++d) vc += (w.v[d][i] - w.v[d][j]) * ci[d];
    s -= (Volume ? m[j] / w.rho[j] : m[j]) * C.own(w, i, r.W[k], r2) * vc;
  }
  return s;
}

template <int D>
class IntegralApproachMatrix final : public PairTermFor<D, IntegralApproachMatrix<D>> {
 public:
  // ghost_base: the first ghost image's index (GhostGenerator::base) when ghost walls are present, so
  // that the wall particles without a matrix are [n_fluid, ghost_base); null: every particle past the fluid.
  explicit IntegralApproachMatrix(std::shared_ptr<IntegralApproachField<D>> C, std::function<std::size_t()> ghost_base = nullptr)
      : C_(std::move(C)), ghost_base_(std::move(ghost_base)) {}
  std::string_view name() const override { return "integral_approach_matrix"; }
  bool feeds_neighbours() const override { return true; }
  bool zero_beyond_support() const override { return C_->kernel == nullptr; }  // W(r, h_i) may reach past kappa h_ij
  void prepare(Workspace<D>& w) const override {
    C_->C.resize(w.n * D * D);
    C_->wall_begin = w.n_fluid;
    C_->wall_end = ghost_base_ ? ghost_base_() : w.n;
  }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    double tau[D * D] = {};
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      double r2 = 0.0;
      for (int d = 0; d < D; ++d) r2 += r.dx[d][k] * r.dx[d][k];
      const double s = m[j] / w.rho[j] * C_->own(w, i, r.W[k], r2);
      for (int a = 0; a < D; ++a)
        for (int b = a; b < D; ++b) tau[a * D + b] += s * r.dx[a][k] * r.dx[b][k];
    }
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < a; ++b) tau[a * D + b] = tau[b * D + a];
    ia_invert<D>(tau, C_->C.data() + i * D * D);
  }

 private:
  std::shared_ptr<IntegralApproachField<D>> C_;
  std::function<std::size_t()> ghost_base_;
};

}  // namespace sphmol
