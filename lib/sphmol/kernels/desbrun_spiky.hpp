#pragma once
// "Spiky" kernel of Desbrun & Cani (1996), listed as Potapov & Reshetnikova 2021, eq 11 with
// support q = r/h <= 2. Potapov & Reshetnikova 2021 prints W = A_D (2 - q)^2, but its constants
// 5/(16 pi h^2) and 15/(64 pi h^3) normalise (2 - q)^3 — Desbrun's original spiky kernel, 15/(pi
// H^6) (H - r)^3 with H = 2h — and not the square (which would need 3/(8 pi h^2)). We implement the
// cubic. Its 1D constant is 1/(8h) by the integral (2 int_0^2 (2-q)^3 dq = 8); the printed 1/(4h)
// is wrong.
#include <numbers>
#include <string_view>

#include "sphmol/kernels/kernel.hpp"

namespace sphmol {

template <int D>
struct DesbrunSpikyKernel : KernelFromEval<DesbrunSpikyKernel<D>> {
  static constexpr int dimension = D;
  static constexpr std::string_view name = "desbrun_spiky";
  static constexpr std::string_view source = "Potapov & Reshetnikova 2021, eq 11 read as (2-q)^3 (Desbrun & Cani 1996); 1D constant from the integral";
  static constexpr double support = 2.0;
  static constexpr bool available = true;
  static constexpr double sigma = D == 1 ? 1.0 / 8.0 : D == 2 ? 5.0 / (16.0 * std::numbers::pi) : 15.0 / (64.0 * std::numbers::pi);

  static void eval(double r, double h, double& w, double& dw) {
    const double q = r / h;
    if (q >= support) { w = dw = 0.0; return; }
    const double a = sigma / h_power<D>(h), t = 2.0 - q;
    w = a * t * t * t;
    dw = -3.0 * a / h * t * t;
  }
};

}  // namespace sphmol
