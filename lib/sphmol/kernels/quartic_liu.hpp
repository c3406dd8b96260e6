#pragma once
// Quartic of Liu (G.R. Liu 2002): Potapov & Reshetnikova 2021, eq 9 (q = r/h <= 2) and Niedoba
// 2012, eq 2.41 (R = r/(kappa h), kappa = 2; substituting R = q/2 gives Potapov & Reshetnikova's
// coefficients exactly). W = A_D (2/3 - 9/8 q^2 + 19/24 q^3 - 5/32 q^4), A_D = 1/h, 15/(7 pi h^2),
// 315/(208 pi h^3); both sources agree and quadrature confirms all three. Note W = -5/32 A_D
// (q-2)^2 (q^2 - 16/15 q - 16/15) is slightly NEGATIVE for 1.6957 < q < 2 (minimum -1.58e-3 A_D at
// q = 1.8); neither source claims positivity.
#include <numbers>
#include <string_view>

#include "sphmol/kernels/kernel.hpp"

namespace sphmol {

template <int D>
struct QuarticLiuKernel : KernelFromEval<QuarticLiuKernel<D>> {
  static constexpr int dimension = D;
  static constexpr std::string_view name = "quartic_liu";
  static constexpr std::string_view source = "Potapov & Reshetnikova 2021, eq 9 / Niedoba 2012, eq 2.41";
  static constexpr double support = 2.0;
  static constexpr bool available = true;
  static constexpr double sigma = D == 1 ? 1.0 : D == 2 ? 15.0 / (7.0 * std::numbers::pi) : 315.0 / (208.0 * std::numbers::pi);

  static void eval(double r, double h, double& w, double& dw) {
    const double q = r / h;
    if (q >= support) { w = dw = 0.0; return; }
    const double a = sigma / h_power<D>(h);
    w = a * (2.0 / 3.0 + q * q * (-9.0 / 8.0 + q * (19.0 / 24.0 - 5.0 / 32.0 * q)));
    dw = a / h * q * (-9.0 / 4.0 + q * (19.0 / 8.0 - 5.0 / 8.0 * q));
  }
};

}  // namespace sphmol
