#pragma once
// Gaussian (Gingold & Monaghan 1977): Vukčević 2012, eq 57, W = alpha_D exp(-q^2), q = r/h.
// The source defines it on all of R^D with alpha_D = pi^(-D/2) h^-D. We truncate it at q = 3
// (the support Potapov & Reshetnikova 2021, eq 6, and Niedoba 2012, eq 2.43, give the Gaussian
// family) and RENORMALISE over
// the truncated ball, so that it integrates to exactly 1:
//   mass_1 = sqrt(pi) erf 3,  mass_2 = pi (1 - e^-9),  mass_3 = pi^(3/2) erf 3 - 6 pi e^-9.
// The unrenormalised variant is truncated_exponential.hpp.
#include <cmath>
#include <numbers>
#include <string_view>

#include "sphmol/kernels/kernel.hpp"

namespace sphmol {

// Integral of exp(-q^2) over the ball q < 3 in R^D.
template <int D>
inline double gaussian_ball_mass() {
  constexpr double pi = std::numbers::pi;
  const double e9 = std::exp(-9.0), erf3 = std::erf(3.0);
  if constexpr (D == 1) return std::sqrt(pi) * erf3;
  else if constexpr (D == 2) return pi * (1.0 - e9);
  else return std::pow(pi, 1.5) * erf3 - 6.0 * pi * e9;
}

template <int D>
struct GaussianKernel : KernelFromEval<GaussianKernel<D>> {
  static constexpr int dimension = D;
  static constexpr std::string_view name = "gaussian";
  static constexpr std::string_view source = "Vukčević 2012, eq 57, truncated at 3h and renormalised";
  static constexpr double support = 3.0;
  static constexpr bool available = true;
  static inline const double sigma = 1.0 / gaussian_ball_mass<D>();

  static void eval(double r, double h, double& w, double& dw) {
    const double q = r / h;
    if (q >= support) { w = dw = 0.0; return; }
    w = sigma / h_power<D>(h) * std::exp(-q * q);
    dw = -2.0 * q / h * w;
  }
};

}  // namespace sphmol
