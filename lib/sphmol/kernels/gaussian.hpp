#pragma once
// Gaussian (Gingold & Monaghan 1977): Vukčević 2012, eq 57, W = alpha_D exp(-q^2), q = r/h.
// The source defines it on all of R^D with alpha_D = pi^(-D/2) h^-D. We truncate it at q = 3
// (the support Potapov & Reshetnikova 2021, eq 6, and Niedoba 2012, eq 2.43, give the Gaussian
// family). Cut off plainly, W and dW/dr would jump at q = 3 (by e^-9 and 6 e^-9 of W(0)): the RHS
// would be discontinuous in the positions, so every pair crossing the support (and every lattice
// pair sitting on it, decided by round-off) leaves a time error that does not shrink with the step.
// We use the shifted-force cut-off of molecular dynamics (Stoddard & Ford 1973; Toxvaerd & Dyre
// 2011), U - U(r_c) - (r - r_c) U'(r_c), taken in s = q^2 so that W stays smooth at q = 0:
//   g(q) = exp(-q^2) - e^-9 (10 - q^2),   g(3) = g'(3) = 0   (W is C1 at the support),
// a shape change of at most 10 e^-9 = 1.2e-3 of W(0). We RENORMALISE over the ball q < 3, so that W
// integrates to exactly 1:
//   mass_1 = sqrt(pi) erf 3 - 42 e^-9,  mass_2 = pi (1 - e^-9) - 49.5 pi e^-9,
//   mass_3 = pi^(3/2) erf 3 - 6 pi e^-9 - 165.6 pi e^-9.
// The unrenormalised variant is truncated_exponential.hpp.
#include <cmath>
#include <numbers>
#include <string_view>

#include "sphmol/kernels/kernel.hpp"

namespace sphmol {

// Integral of exp(-q^2) over the ball q < 3 in R^D (the plain cut-off).
template <int D>
inline double plain_gaussian_ball_mass() {
  constexpr double pi = std::numbers::pi;
  const double e9 = std::exp(-9.0), erf3 = std::erf(3.0);
  if constexpr (D == 1) return std::sqrt(pi) * erf3;
  else if constexpr (D == 2) return pi * (1.0 - e9);
  else return std::pow(pi, 1.5) * erf3 - 6.0 * pi * e9;
}

// Integral of the shifted-force Gaussian g(q) over the ball q < 3 in R^D: that of exp(-q^2) minus
// e^-9 times that of 10 - q^2 (2 * 21, 2 pi * 24.75, 4 pi * 41.4).
template <int D>
inline double gaussian_ball_mass() {
  constexpr double pi = std::numbers::pi;
  const double e9 = std::exp(-9.0);
  constexpr double poly = D == 1 ? 42.0 : D == 2 ? 49.5 * pi : 165.6 * pi;
  return plain_gaussian_ball_mass<D>() - poly * e9;
}

// g(q) and dg/dq of the shifted-force Gaussian (above); 0 for q >= 3.
inline void shifted_force_gaussian(double q, double& g, double& dg) {
  if (q >= 3.0) { g = dg = 0.0; return; }
  const double e9 = std::exp(-9.0);  // folded at compile time
  const double e = std::exp(-q * q);
  g = e - e9 * (10.0 - q * q);
  dg = -2.0 * q * (e - e9);
}

template <int D>
struct GaussianKernel : KernelFromEval<GaussianKernel<D>> {
  static constexpr int dimension = D;
  static constexpr std::string_view name = "gaussian";
  static constexpr std::string_view source =
      "Vukčević 2012, eq 57, truncated at 3h with the shifted-force cut-off (C1) and renormalised";
  static constexpr double support = 3.0;
  static constexpr bool available = true;
  static inline const double sigma = 1.0 / gaussian_ball_mass<D>();

  static void eval(double r, double h, double& w, double& dw) {
    double g, dg;
    shifted_force_gaussian(r / h, g, dg);
    const double a = sigma / h_power<D>(h);
    w = a * g;
    dw = a / h * dg;
  }
};

}  // namespace sphmol
