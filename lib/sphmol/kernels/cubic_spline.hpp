#pragma once
// Cubic B-spline (Monaghan & Lattanzio 1985): Vukčević et al. 2012, eq 15, Vukčević 2012, eq 58,
// Potapov & Reshetnikova 2021, eq 8. W = alpha_D (2/3 - R^2 + R^3/2) for R < 1, alpha_D/6 (2-R)^3
// for 1 <= R < 2, R = r/h. alpha_D = 1/h, 15/(7 pi h^2), 3/(2 pi h^3) in 1D/2D/3D;
// tests/unit/test_kernel_normalisation.cpp checks each by GSL quadrature.
#include <numbers>

#include "sphmol/kernels/kernel.hpp"
#include <string_view>

namespace sphmol {

template <int D>
struct CubicSpline : KernelFromEval<CubicSpline<D>> {
  static constexpr int dimension = D;
  static constexpr std::string_view name = "cubic_spline";
  static constexpr std::string_view source = "Vukčević 2012, eq 58 / Potapov & Reshetnikova 2021, eq 8 / Niedoba 2012, eq 2.40";
  static constexpr double support = 2.0;
  static constexpr bool available = true;
  static constexpr double sigma = D == 1 ? 1.0 : D == 2 ? 15.0 / (7.0 * std::numbers::pi) : 3.0 / (2.0 * std::numbers::pi);

  static double norm(double h) {
    double hd = h;
    for (int d = 1; d < D; ++d) hd *= h;
    return sigma / hd;
  }
  // Branch-free form of the same spline, (1/6)[(2-q)+^3 - 4(1-q)+^3]: the pair loop evaluates it
  // for neighbours on both sides of q = 1, where a branch would be mispredicted half the time.
  static void eval(double r, double h, double& w, double& dw) {
    const double q = r / h, a = norm(h);
    const double t2 = q < 2.0 ? 2.0 - q : 0.0, t1 = q < 1.0 ? 1.0 - q : 0.0;
    w = a / 6.0 * (t2 * t2 * t2 - 4.0 * t1 * t1 * t1);
    dw = a / h * (2.0 * t1 * t1 - 0.5 * t2 * t2);
  }
};

}  // namespace sphmol
