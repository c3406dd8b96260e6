#pragma once
// Discrete particle-consistency sums at a point x (Vukčević 2012, eqs 90-91, and their gradient
// analogues, the discrete form of eq 69):
//   S0  = sum_b W(x - x_b) V_b                       -> 1   (eq 90, constant consistency)
//   S1  = sum_b (x - x_b) W(x - x_b) V_b             -> 0   (eq 91; printed "= 1" in Vukčević 2012,
//                                                         but it is the discrete eq 87, = 0)
//   G0  = sum_b grad_x W(x - x_b) V_b                -> 0
//   G1  = sum_b (x_b - x) (x) grad_x W(x - x_b) V_b  -> identity (gradient of a linear field)
#include <array>
#include <cmath>

#include "sphmol/analysis/particle_sets.hpp"
#include "sphmol/kernels/registry.hpp"

namespace sphmol::analysis {

template <int D>
struct ConsistencySums {
  double S0 = 0.0;
  std::array<double, D> S1{};
  std::array<double, D> G0{};
  std::array<std::array<double, D>, D> G1{};  // G1[a][b] = sum (x_b - x)_a (grad W)_b V
  int neighbours = 0;                         // particles inside the support
};

template <int D>
ConsistencySums<D> consistency_sums(const ParticleSet<D>& set, const std::array<double, D>& x, double h,
                                    const KernelInfo<D>& kernel, double k_smoothing = 0.0) {
  ConsistencySums<D> s;
  for (std::size_t b = 0; b < set.x.size(); ++b) {
    std::array<double, D> dx;
    double r2 = 0.0;
    for (int a = 0; a < D; ++a) {
      dx[a] = x[a] - set.x[b][a];
      r2 += dx[a] * dx[a];
    }
    const double r = std::sqrt(r2);
    if (r >= kernel.support * h) continue;
    ++s.neighbours;
    const double w = kernel.W(r, h) * set.V[b];
    // grad_x W = W'(r) dx / r; with k_smoothing = h/d > 0 the k-dependent derivative is used
    // (Potapov & Reshetnikova 2021, eq 13b for the composite kernel).
    const double dw = k_smoothing > 0.0 ? kernel.dWdr_k(r, h, k_smoothing) : kernel.dWdr(r, h);
    const double f = r > 0.0 ? dw / r * set.V[b] : 0.0;
    s.S0 += w;
    for (int a = 0; a < D; ++a) {
      s.S1[a] += dx[a] * w;
      s.G0[a] += f * dx[a];
      for (int c = 0; c < D; ++c) s.G1[a][c] += -dx[a] * f * dx[c];
    }
  }
  return s;
}

}  // namespace sphmol::analysis
