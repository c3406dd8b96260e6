#pragma once
// A C-infinity step: S(t) = 0 for t <= 0, 1 for t >= 1, and in between
//   S(t) = psi(t) / (psi(t) + psi(1 - t)),  psi(t) = exp(-1/t)   (Tu 2011, §13.1),
// written with one exponential as 1 / (1 + exp(1/t - 1/(1 - t))), the exponent in one division as
// ((1 - t) - t) / (t (1 - t)). Every derivative of S vanishes at t = 0 and t = 1, so a switch or
// cut-off built as x S(x / delta) is C-infinity where the plain min / cut-off has a kink: a fixed-step
// integrator of order p then keeps order p across it (a kink, crossed a fixed number of times, caps
// every method at order 2; docs/verification.md). The Gaussian kernels' taper uses it. Its
// derivatives grow faster than k!, so a band shows Verner's order only once a step covers a small
// part of a crossing; the dynamic walls' density floor and the viscosity switch use the C^6 polynomial
// step of core/polynomial_step.hpp instead, and the taper keeps this one: with P there the 2D Sod
// tube leaves its bounds (docs/verification.md, "A polynomial step").
// Branch-free (the clamp is a min/max, 1/0 = inf, and the exponential of core/lane_exp.hpp gives
// exp(+inf) = inf and exp(-inf) < 1e-307, so S(0) = 0 and S(1) = 1 exactly) and with no library
// call, so it vectorises where the caller's loop does, and smooth_step(V) takes four lanes at once
// (AVX2), each the scalar's number bit for bit.
#include <cmath>

#include "sphmol/core/lane_exp.hpp"

namespace sphmol {

// S(t) for a double or (AVX2) four lanes; NaN (0/0, from a zero-width band at x = 0) reads as t <= 0.
template <class V>
[[gnu::always_inline]] inline V smooth_step_lanes(V t) {
  const V one = lane_ops::constant<V>(1.0), c = lane_ops::clamp01(t), d = one - c;
  return one / (one + lane_exp((d - c) / (c * d)));  // 1/c - 1/(1 - c) in one division; +-inf at c = 0, 1
}
inline double smooth_step(double t) { return smooth_step_lanes(t); }

// S(t) and dS/dt. dS/dt = S (1 - S) (1/t^2 + 1/(1 - t)^2), with S (1 - S) = e / (1 + e)^2 taken in
// whichever of e = exp(u), exp(-u) does not overflow.
inline void smooth_step(double t, double& s, double& ds) {
  if (!(t > 0.0)) { s = ds = 0.0; return; }
  if (t >= 1.0) { s = 1.0; ds = 0.0; return; }
  const double u = ((1.0 - t) - t) / (t * (1.0 - t));  // as smooth_step(t)
  const double e = std::exp(-std::abs(u));  // <= 1
  const double inv = 1.0 / (1.0 + e);
  s = u > 0.0 ? e * inv : inv;
  ds = e * inv * inv * (1.0 / (t * t) + 1.0 / ((1.0 - t) * (1.0 - t)));
}

}  // namespace sphmol
