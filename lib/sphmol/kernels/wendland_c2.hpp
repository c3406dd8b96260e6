#pragma once
// Wendland C2 kernel (Wendland 1995, Adv. Comput. Math. 4:389) — not in the SPH texts the other
// kernels come from; needed for the
// dam-break case. psi_{3,1}(R) = (1 - R)^4 (4R + 1) is positive definite in D <= 3; with
// R = q/2 (support 2h) it reads (1 - q/2)^4 (2q + 1). Constants from the integral:
// A_D = 3/(4h), 7/(4 pi h^2), 21/(16 pi h^3).
#include <cmath>
#include <numbers>
#include <string_view>

#include "sphmol/kernels/kernel.hpp"

namespace sphmol {

template <int D>
struct WendlandC2Kernel : KernelFromEval<WendlandC2Kernel<D>> {
  static constexpr int dimension = D;
  static constexpr std::string_view name = "wendland_c2";
  static constexpr std::string_view source = "Wendland 1995 psi_3,1 ";
  static constexpr double support = 2.0;
  static constexpr bool available = true;
  static constexpr double sigma = D == 1 ? 0.75 : D == 2 ? 7.0 / (4.0 * std::numbers::pi) : 21.0 / (16.0 * std::numbers::pi);

  static void eval(double r, double h, double& w, double& dw) {
    const double q = r / h;
    if (q >= support) { w = dw = 0.0; return; }
    const double a = sigma / h_power<D>(h), t = 1.0 - 0.5 * q, t3 = t * t * t;
    w = a * t3 * t * (2.0 * q + 1.0);
    dw = -5.0 * a / h * q * t3;
  }
  // (dW/dq)/q = -5 sigma t^3 needs no division, and t clamped at 0 makes the value 0 outside the
  // support. The clamp is written (u + |u|)/2, exact, because compilers turn max(0, u) into a branch
  // here, which mispredicts on the skin pairs the fused kernel pass evaluates and discards.
  static void eval_unit_over_r(double q, double& w, double& f) {
    const double u = 1.0 - 0.5 * q, t = 0.5 * (u + std::fabs(u)), t3 = t * t * t;
    w = sigma * t3 * t * (2.0 * q + 1.0);
    f = -5.0 * sigma * t3;
  }
};

}  // namespace sphmol
