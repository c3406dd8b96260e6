#pragma once
// Quadratic kernel of Johnson et al. (1996): Potapov & Reshetnikova 2021, eq 10 (q = r/h <= 2) and
// Niedoba 2012, eq 2.44 (R = r/(kappa h), kappa = 2). W = A_D (3/4 - 3/4 q + 3/16 q^2), A_D = 1/h,
// 2/(pi h^2), 5/(4 pi h^3); both sources agree and quadrature confirms them. Its derivative does
// not vanish at q = 0 (dW/dr = -3/4 A_D/h), the known reason it is used for impacts and not for
// fluids.
#include <numbers>
#include <string_view>

#include "sphmol/kernels/kernel.hpp"

namespace sphmol {

template <int D>
struct QuadraticJohnsonKernel : KernelFromEval<QuadraticJohnsonKernel<D>> {
  static constexpr int dimension = D;
  static constexpr std::string_view name = "quadratic_johnson";
  static constexpr std::string_view source = "Potapov & Reshetnikova 2021, eq 10 / Niedoba 2012, eq 2.44";
  static constexpr double support = 2.0;
  static constexpr bool available = true;
  static constexpr double sigma = D == 1 ? 1.0 : D == 2 ? 2.0 / std::numbers::pi : 5.0 / (4.0 * std::numbers::pi);

  static void eval(double r, double h, double& w, double& dw) {
    const double q = r / h;
    if (q >= support) { w = dw = 0.0; return; }
    const double a = sigma / h_power<D>(h);
    w = a * (0.75 - 0.75 * q + 0.1875 * q * q);
    dw = a / h * (-0.75 + 0.375 * q);
  }
};

}  // namespace sphmol
