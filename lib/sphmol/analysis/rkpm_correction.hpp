#pragma once
// RKPM / moment-matrix kernel correction restoring linear consistency for one particle i
// (Vukčević 2012, eqs 92-99 with delta = 1; Niedoba 2012, eqs 2.80-2.86). The corrected kernel is
//   W~_ij = W_ij * beta . p_j,   p_j = (1, (x_i - x_j)/L),
// with beta from the (D+1)x(D+1) moment matrix M = sum_j V_j W_ij p_j p_j^T (eq 99 with the
// SPH kernel as window function, eqs 96-97: M beta = e_0). Then sum_j V_j W~_ij f_j = f_i for
// every linear f (eq 93 / 2.85). The corrected gradient is the exact x_i-derivative of W~_ij
// (neighbour positions and volumes fixed), so it reproduces the gradient of linear fields too:
//   d_a M  = sum_j V_j [(e_a p_j^T + p_j e_a^T) W_ij / L + p_j p_j^T F_ij dx_ij,a]
//   d_a beta = -M^-1 (d_a M) beta
//   d_a W~_ij = W_ij (d_a beta . p_j + beta_a / L) + (beta . p_j) F_ij dx_ij,a
// where grad_i W_ij = F_ij dx_ij. L is a length scale (the largest |dx|) that keeps M well
// conditioned whatever the units. Include the self pair (dx = 0) if it belongs to the sum.
// Lives in analysis/ for now; the solver's right-hand side can call it per particle.
#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

namespace sphmol::analysis {

// Returns false (outputs untouched) when the moment matrix is singular, e.g. too few or
// collinear neighbours; the caller then keeps the uncorrected kernel.
template <int D>
bool rkpm_correct(std::span<const std::array<double, D>> dx, std::span<const double> V,
                  std::span<const double> W, std::span<const double> F, std::span<double> W_corr,
                  std::span<std::array<double, D>> gradW_corr) {
  using Vec = Eigen::Matrix<double, D + 1, 1>;
  using Mat = Eigen::Matrix<double, D + 1, D + 1>;
  const std::size_t n = dx.size();
  double L = 0.0;
  for (const auto& v : dx) {
    double r2 = 0.0;
    for (double c : v) r2 += c * c;
    L = std::max(L, std::sqrt(r2));
  }
  if (L == 0.0) return false;
  auto p_of = [&](std::size_t j) {
    Vec p;
    p(0) = 1.0;
    for (int a = 0; a < D; ++a) p(a + 1) = dx[j][a] / L;
    return p;
  };
  Mat M = Mat::Zero();
  for (std::size_t j = 0; j < n; ++j) {
    const Vec p = p_of(j);
    M += V[j] * W[j] * p * p.transpose();
  }
  Eigen::FullPivLU<Mat> lu(M);
  if (!lu.isInvertible()) return false;
  const Vec beta = lu.solve(Vec::Unit(0));
  std::array<Vec, D> dbeta;
  for (int a = 0; a < D; ++a) {
    Mat dM = Mat::Zero();
    const Vec ea = Vec::Unit(a + 1);
    for (std::size_t j = 0; j < n; ++j) {
      const Vec p = p_of(j);
      dM += V[j] * ((ea * p.transpose() + p * ea.transpose()) * (W[j] / L) + p * p.transpose() * (F[j] * dx[j][a]));
    }
    dbeta[a] = -lu.solve(dM * beta);
  }
  for (std::size_t j = 0; j < n; ++j) {
    const Vec p = p_of(j);
    const double bp = beta.dot(p);
    W_corr[j] = W[j] * bp;
    for (int a = 0; a < D; ++a)
      gradW_corr[j][a] = W[j] * (dbeta[a].dot(p) + beta(a + 1) / L) + bp * F[j] * dx[j][a];
  }
  return true;
}

}  // namespace sphmol::analysis
