#pragma once
// Gaussian (Gingold & Monaghan 1977): Vukčević 2012, eq 57, W = alpha_D exp(-q^2), q = r/h.
// The source defines it on all of R^D with alpha_D = pi^(-D/2) h^-D. We truncate it at q = 3
// (the support Potapov & Reshetnikova 2021, eq 6, and Niedoba 2012, eq 2.43, give the Gaussian
// family). Cut off plainly, W and dW/dr would jump at q = 3 (by e^-9 and 6 e^-9 of W(0)): the RHS
// would be discontinuous in the positions, so every pair crossing the support (and every lattice
// pair sitting on it, decided by round-off) leaves a time error that does not shrink with the step.
// A cut-off that is C^m at q = 3 still caps every fixed-step integrator at order m + 1 (the number of
// support crossings does not depend on the step; docs/verification.md, "Time-error floor"), so we
// taper the Gaussian to zero with the C-infinity step S of core/smooth_step.hpp:
//   g(q) = exp(-q^2) (1 - S((q - q_t) / (3 - q_t))),   q_t = 2.5,
// exactly exp(-q^2) for q <= q_t and with every derivative zero at q = 3. Beyond q_t the Gaussian is
// below e^-6.25 = 1.9e-3 of W(0), so the shape changes by at most that (the shifted-force cut-off
// of molecular dynamics, exp(-q^2) - e^-9 (10 - q^2), changed it by 1.2e-3 and was only C1). We
// RENORMALISE over the ball q < 3, so that W integrates to exactly 1; the taper's share of the mass
// has no closed form and is integrated once (Simpson, error far below round-off: the integrand is
// smooth). The unrenormalised variant is truncated_exponential.hpp.
#include <cmath>
#include <numbers>
#include <string_view>

#include "sphmol/core/smooth_step.hpp"
#include "sphmol/kernels/kernel.hpp"

namespace sphmol {

// Where the taper starts, in q = r/h.
inline constexpr double kGaussianTaperStart = 2.5;

// Integral of exp(-q^2) over the ball q < 3 in R^D (the plain cut-off).
template <int D>
inline double plain_gaussian_ball_mass() {
  constexpr double pi = std::numbers::pi;
  const double e9 = std::exp(-9.0), erf3 = std::erf(3.0);
  if constexpr (D == 1) return std::sqrt(pi) * erf3;
  else if constexpr (D == 2) return pi * (1.0 - e9);
  else return std::pow(pi, 1.5) * erf3 - 6.0 * pi * e9;
}

// g(q) and dg/dq of the tapered Gaussian (above); 0 for q >= 3.
inline void tapered_gaussian(double q, double& g, double& dg) {
  if (q >= 3.0) { g = dg = 0.0; return; }
  const double e = std::exp(-q * q);
  if (q <= kGaussianTaperStart) { g = e; dg = -2.0 * q * e; return; }
  // 1 - S(t) = S(1 - t), taken so: 1 - S would round to 0 while S(1 - t) is still ~ 1e-300.
  constexpr double width = 3.0 - kGaussianTaperStart;
  double s, ds;
  smooth_step((3.0 - q) / width, s, ds);
  g = e * s;
  dg = -2.0 * q * g - e * ds / width;
}

// Integral of the tapered Gaussian g(q) over the ball q < 3 in R^D: that of exp(-q^2) minus the
// taper's share, int_{q_t}^3 exp(-q^2) S(.) |S^(D-1)| q^(D-1) dq, by composite Simpson.
template <int D>
inline double gaussian_ball_mass() {
  constexpr double pi = std::numbers::pi;
  constexpr double sphere = D == 1 ? 2.0 : D == 2 ? 2.0 * pi : 4.0 * pi;  // |S^(D-1)|
  constexpr int n = 4096;                                                 // intervals (even)
  constexpr double a = kGaussianTaperStart, dq = (3.0 - a) / n;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double q = a + k * dq;
    double g, dg;
    tapered_gaussian(q, g, dg);
    const double cut = std::exp(-q * q) - g;  // exp(-q^2) S((q - q_t) / (3 - q_t))
    const double wk = k == 0 || k == n ? 1.0 : (k % 2 ? 4.0 : 2.0);
    sum += wk * cut * sphere * std::pow(q, D - 1);
  }
  return plain_gaussian_ball_mass<D>() - sum * dq / 3.0;
}

template <int D>
struct GaussianKernel : KernelFromEval<GaussianKernel<D>> {
  static constexpr int dimension = D;
  static constexpr std::string_view name = "gaussian";
  static constexpr std::string_view source =
      "Vukčević 2012, eq 57, tapered to zero over 2.5h-3h (C-infinity) and renormalised";
  static constexpr double support = 3.0;
  static constexpr bool available = true;
  static inline const double sigma = 1.0 / gaussian_ball_mass<D>();

  static void eval(double r, double h, double& w, double& dw) {
    double g, dg;
    tapered_gaussian(r / h, g, dg);
    const double a = sigma / h_power<D>(h);
    w = a * g;
    dw = a / h * dg;
  }
};

}  // namespace sphmol
