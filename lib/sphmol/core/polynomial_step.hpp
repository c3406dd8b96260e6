#pragma once
// A C^m step, m = kPolynomialStepOrder: P(t) = 0 for t <= 0, 1 for t >= 1, and in between the smoothstep
// polynomial of degree 2m + 1, the regularised incomplete beta function
//   P(t) = I_t(m + 1, m + 1) = sum_{j=m+1}^{2m+1} binom(2m+1, j) t^j (1 - t)^(2m+1-j)   (Olver et al. 2010, eq 8.17.5),
//   P'(t) = (2m + 1) binom(2m, m) t^m (1 - t)^m,
// evaluated as the same sum in the form with positive terms only,
//   P(t) = t^(m+1) sum_{j=0}^{m} binom(m + j, j) (1 - t)^j
// (Horner in 1 - t, positive terms: no cancellation, so P is accurate to a few ulp relative to itself
// near 0; P(0) = 0, P(1) = 1 exactly). Its first m derivatives vanish at t = 0 and t = 1, so a floor built as
// x P(x / delta) is C^m where the plain max has a kink, and f(t, y) with it: each of the fixed number
// of crossings costs O(dt^(m+2)), which caps a fixed-step integrator at order m + 2, at m = 6 above
// Verner 8(5)6's 6 (docs/verification.md, "Time-error floor").
// Unlike the C-infinity step of core/smooth_step.hpp, 1 / (1 + exp(1/t - 1/(1 - t))) (Tu 2011, §13.1),
// its derivatives stay small: max |P^(k)| / k! = 2.9, 6.6, 24, 56, 141, 287 for k = 1 ... 6 (m = 6),
// against 2.0, 4.9, 18, 95, 643, 6.7e3, so a step resolves a crossing of its band at a coarser step
// and Verner's order shows at larger errors (docs/verification.md, "A polynomial step"). The dynamic
// walls' density floor (smooth_max0, below) and the viscosity switch (physics/artificial_viscosity.hpp,
// with the shock tubes' band offset 0.3, P(0.3) = 0.062) use it; the Gaussian kernels' taper keeps
// the C-infinity step: with this one the 2D Sod tube leaves its bounds (the same section).
// Branch-free (the clamp is a min/max) multiplies and adds with no library call, so it vectorises where
// the caller's loop does, and polynomial_step_lanes takes four lanes at once (AVX2), each the scalar's
// number bit for bit (the build's -ffp-contract=off keeps the operations unfused in both).
#include <array>

#include "sphmol/core/lane_exp.hpp"  // lane_ops

namespace sphmol {

// m: P is C^m at 0 and 1 (its (m + 1)-th derivative jumps there).
inline constexpr int kPolynomialStepOrder = 6;

// binom(m + j, j), j = 0 ... m: Horner's coefficients.
constexpr std::array<double, kPolynomialStepOrder + 1> polynomial_step_coefficients() {
  std::array<double, kPolynomialStepOrder + 1> a{};
  double b = 1.0;
  for (int j = 0; j <= kPolynomialStepOrder; ++j) {
    a[j] = b;
    b = b * (kPolynomialStepOrder + j + 1) / (j + 1);
  }
  return a;
}

// P(t) for a double or (AVX2) four lanes; NaN reads as t <= 0.
template <class V>
[[gnu::always_inline]] inline V polynomial_step_lanes(V t) {
  // On the half nearer the end, x = min(c, 1 - c) <= 1/2 (1 - c is exact for c >= 1/2), and
  // P(c) = 1 - P(1 - c) above 1/2: so P <= 1, P(t) + P(1 - t) = 1 to an ulp, and 1 - P near t = 1 is
  // as accurate as P near 0.
  using lane_ops::constant;
  const V one = constant<V>(1.0), half = constant<V>(0.5);
  const V c = lane_ops::clamp01(t), x = lane_ops::min(c, one - c), d = one - x;
  constexpr auto a = polynomial_step_coefficients();
  V h = constant<V>(a[kPolynomialStepOrder]);
  for (int j = kPolynomialStepOrder - 1; j >= 0; --j) h = h * d + constant<V>(a[j]);
  V p = x;
  for (int j = 0; j < kPolynomialStepOrder; ++j) p = p * x;  // x^(m+1)
  const V q = p * h;
  return lane_ops::select_gt(c, half, one - q, q);
}
inline double polynomial_step(double t) { return polynomial_step_lanes(t); }

// A C^m max(x, 0): x P(x / width). Equal to x for x >= width, 0 for x <= 0, in [0, x] between;
// width = 0 gives max(x, 0) exactly.
inline double smooth_max0(double x, double width) { return x * polynomial_step(x / width); }

}  // namespace sphmol
