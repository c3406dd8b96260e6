#pragma once
// Exponential (truncated Gaussian) of Niedoba 2012, eq 2.43: W = alpha_D exp(-(3R)^2) for R < 1
// with R = r/(kappa h), kappa = 3. In q = r/h that is exp(-q^2) for q < 3, and alpha_D =
// 3/(sqrt(pi) kappa h), 9/(pi kappa^2 h^2), 27/(pi^(3/2) kappa^3 h^3) becomes pi^(-D/2) h^-D: the
// constant of the UNtruncated Gaussian. We keep the source's constant (not renormalised), so the
// kernel integrates to mass() = 1 - (Gaussian tail beyond 3h): erf 3, 1 - e^-9, erf 3 - 6
// e^-9/sqrt(pi) (about 1 - 2.2e-5, 1 - 1.2e-4, 1 - 4.4e-4). Its jump of W at the support edge is
// what Niedoba 2012 warns about; gaussian.hpp is the renormalised variant.
#include <cmath>
#include <numbers>
#include <string_view>

#include "sphmol/kernels/gaussian.hpp"
#include "sphmol/kernels/kernel.hpp"

namespace sphmol {

template <int D>
struct TruncatedExponentialKernel : KernelFromEval<TruncatedExponentialKernel<D>> {
  static constexpr int dimension = D;
  static constexpr std::string_view name = "truncated_exponential";
  static constexpr std::string_view source = "Niedoba 2012, eq 2.43 (kappa = 3), printed constant, not renormalised";
  static constexpr double support = 3.0;
  static constexpr bool available = true;
  static inline const double sigma = std::pow(std::numbers::pi, -0.5 * D);
  static double mass() { return sigma * gaussian_ball_mass<D>(); }

  static void eval(double r, double h, double& w, double& dw) {
    const double q = r / h;
    if (q >= support) { w = dw = 0.0; return; }
    w = sigma / h_power<D>(h) * std::exp(-q * q);
    dw = -2.0 * q / h * w;
  }
};

}  // namespace sphmol
