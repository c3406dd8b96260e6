#pragma once
// Lucy (1977) bell-shaped quartic: Vukčević 2012, eq 55, W = alpha_D (1 + 3q)(1 - q)^3 for q = r/h
// < 1. alpha_D = 5/(4h), 5/(pi h^2), 105/(16 pi h^3) as printed; all three confirmed by quadrature.
#include <numbers>
#include <string_view>

#include "sphmol/kernels/kernel.hpp"

namespace sphmol {

template <int D>
struct LucyKernel : KernelFromEval<LucyKernel<D>> {
  static constexpr int dimension = D;
  static constexpr std::string_view name = "lucy";
  static constexpr std::string_view source = "Vukčević 2012, eq 55 (Lucy 1977)";
  static constexpr double support = 1.0;
  static constexpr bool available = true;
  static constexpr double sigma = D == 1 ? 5.0 / 4.0 : D == 2 ? 5.0 / std::numbers::pi : 105.0 / (16.0 * std::numbers::pi);

  static void eval(double r, double h, double& w, double& dw) {
    const double q = r / h;
    if (q >= 1.0) { w = dw = 0.0; return; }
    const double a = sigma / h_power<D>(h), t = 1.0 - q;
    w = a * (1.0 + 3.0 * q) * t * t * t;
    dw = a / h * (-12.0 * q * t * t);
  }
};

}  // namespace sphmol
