#pragma once
// Quintic spline of Morris (1997): Potapov & Reshetnikova 2021, eq 7 (q = r/h <= 3) and Niedoba
// 2012, eq 2.42 (R = r/(kappa h), kappa = 3: 81/22 (1-R)^5 = (3-q)^5 / 66 etc., the same shape).
// W = A_D [(3-q)^5 - 6(2-q)^5 + 15(1-q)^5] with the terms switched off beyond q = 1, 2, 3.
// Integral: int_0^a (a-q)^5 q^(D-1) dq = a^(D+5) (D-1)! 5!/(D+5)!, so the correct constants are
//   A_1 = 1/(120 h), A_2 = 7/(478 pi h^2), A_3 = 1/(120 pi h^3).
// Potapov & Reshetnikova 2021 prints 120/h (inverted) and 3/(395 pi h^3) (wrong; the literature's
// 3/(359 pi) is also off by 0.3%); Niedoba's 33/20, 2079/239, 297/20 over kappa^D agree with the
// integral.
#include <numbers>
#include <string_view>

#include "sphmol/kernels/kernel.hpp"

namespace sphmol {

template <int D>
struct QuinticMorrisKernel : KernelFromEval<QuinticMorrisKernel<D>> {
  static constexpr int dimension = D;
  static constexpr std::string_view name = "quintic_morris";
  static constexpr std::string_view source = "Potapov & Reshetnikova 2021, eq 7 / Niedoba 2012, eq 2.42 (constants from the integral)";
  static constexpr double support = 3.0;
  static constexpr bool available = true;
  static constexpr double sigma = D == 1 ? 1.0 / 120.0 : D == 2 ? 7.0 / (478.0 * std::numbers::pi) : 1.0 / (120.0 * std::numbers::pi);

  static void eval(double r, double h, double& w, double& dw) {
    const double q = r / h;
    if (q >= support) { w = dw = 0.0; return; }
    const double a = sigma / h_power<D>(h);
    double f = 0.0, df = 0.0;
    auto term = [&](double c, double edge) {
      if (q < edge) {
        const double t = edge - q, t2 = t * t, t4 = t2 * t2;
        f += c * t4 * t;
        df -= 5.0 * c * t4;
      }
    };
    term(1.0, 3.0);
    term(-6.0, 2.0);
    term(15.0, 1.0);
    w = a * f;
    dw = a / h * df;
  }
};

}  // namespace sphmol
