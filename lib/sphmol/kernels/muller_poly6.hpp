#pragma once
// Poly6 kernel of Mueller, Charypar & Gross (2003): Potapov & Reshetnikova 2021, eq 12, W = A_D (1
// - q^2)^3 for q = r/h <= 1. Printed A_D = 35/(16h), 4/(pi h^2), 315/(64 pi h^3). The 2D and 3D
// constants match the integral; the 1D one does not: 2 int_0^1 (1-q^2)^3 dq = 32/35, so A_1 =
// 35/(32h).
#include <numbers>
#include <string_view>

#include "sphmol/kernels/kernel.hpp"

namespace sphmol {

template <int D>
struct MullerPoly6Kernel : KernelFromEval<MullerPoly6Kernel<D>> {
  static constexpr int dimension = D;
  static constexpr std::string_view name = "muller_poly6";
  static constexpr std::string_view source = "Potapov & Reshetnikova 2021, eq 12 (1D constant from the integral)";
  static constexpr double support = 1.0;
  static constexpr bool available = true;
  static constexpr double sigma = D == 1 ? 35.0 / 32.0 : D == 2 ? 4.0 / std::numbers::pi : 315.0 / (64.0 * std::numbers::pi);

  static void eval(double r, double h, double& w, double& dw) {
    const double q = r / h;
    if (q >= support) { w = dw = 0.0; return; }
    const double a = sigma / h_power<D>(h), t = 1.0 - q * q;
    w = a * t * t * t;
    dw = -6.0 * a / h * q * t * t;
  }
};

}  // namespace sphmol
