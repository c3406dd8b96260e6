#pragma once
// Composite kernel of Potapov & Reshetnikova 2021, eqs 13a/13b, 2D only (the source gives
// only the 2D modification), support q = r/h <= 1 with h = k d.
//   13a: W = 15/(13 h^2) (1 - q^2)^2 (1 - c q^2),  c = 4 - 52/(5 pi).
//        (Integral: pi int_0^1 (1-u)^2 (1 - c u) du = pi (1/3 - c/12) = 13/15, so the printed
//        constant is right.)
//   13b: dW/dr = -1369 k^2 / (28 pi h^3 (74k - 63)) (84k/37 - 2q)
// The derivative is a separate generating function, NOT d/dr of 13a, and it depends on the
// smoothing coefficient k = h/d itself (pole at k = 63/74). dWdr_k(r, h, k) is eq 13b;
// dWdr(r, h) is eq 13b at k = 1 (h = d). Both are 0 for q >= 1 (13b itself is nonzero at q = 1).
#include <numbers>
#include <string_view>

#include "sphmol/kernels/kernel.hpp"

namespace sphmol {

template <int D>
struct CompositeKernel {
  static constexpr int dimension = D;
  static constexpr std::string_view name = "composite";
  static constexpr std::string_view source = "Potapov & Reshetnikova 2021, eqs 13a (value) and 13b (separate derivative), 2D only";
  static constexpr std::string_view unavailable_reason =
      "Potapov & Reshetnikova 2021 gives the composite kernel (eq 13a value, eq 13b separate derivative) only for 2D";
  static constexpr double support = 1.0;
  static constexpr bool available = D == 2;
  static constexpr bool derivative_is_exact = false;
  static constexpr double c = 4.0 - 52.0 / (5.0 * std::numbers::pi);

  static double W(double r, double h) {
    const double q = r / h;
    if (q >= 1.0) return 0.0;
    const double t = 1.0 - q * q;
    return 15.0 / (13.0 * h * h) * t * t * (1.0 - c * q * q);
  }
  static double dWdr_k(double r, double h, double k) {
    const double q = r / h;
    if (q >= 1.0) return 0.0;
    return -1369.0 * k * k / (28.0 * std::numbers::pi * h * h * h * (74.0 * k - 63.0)) * (84.0 / 37.0 * k - 2.0 * q);
  }
  static double dWdr(double r, double h) { return dWdr_k(r, h, 1.0); }
  static void eval(double r, double h, double& w, double& dw) {
    w = W(r, h);
    dw = dWdr(r, h);
  }
};

}  // namespace sphmol
