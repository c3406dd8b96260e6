#pragma once
// The discrete consistency sums of particle_consistency.hpp evaluated with the RKPM-corrected
// kernel (rkpm_correction.hpp): the option that restores linear consistency where the support is
// truncated, e.g. next to a wall. With the correction S0 = 1, S1 = 0, G0 = 0 and G1 = I to round-off.
#include <vector>

#include "sphmol/analysis/particle_consistency.hpp"
#include "sphmol/analysis/rkpm_correction.hpp"

namespace sphmol::analysis {

// Returns false when the moment matrix is singular (too few neighbours); `out` is then untouched.
template <int D>
bool rkpm_consistency_sums(const ParticleSet<D>& set, const std::array<double, D>& x, double h,
                           const KernelInfo<D>& kernel, double k_smoothing, ConsistencySums<D>& out) {
  std::vector<std::array<double, D>> dx;
  std::vector<double> V, W, F;
  for (std::size_t b = 0; b < set.x.size(); ++b) {
    std::array<double, D> d;
    double r2 = 0.0;
    for (int a = 0; a < D; ++a) {
      d[a] = x[a] - set.x[b][a];
      r2 += d[a] * d[a];
    }
    const double r = std::sqrt(r2);
    if (r >= kernel.support * h) continue;
    const double dw = k_smoothing > 0.0 ? kernel.dWdr_k(r, h, k_smoothing) : kernel.dWdr(r, h);
    dx.push_back(d);
    V.push_back(set.V[b]);
    W.push_back(kernel.W(r, h));
    F.push_back(r > 0.0 ? dw / r : 0.0);
  }
  std::vector<double> Wc(dx.size());
  std::vector<std::array<double, D>> Gc(dx.size());
  if (!rkpm_correct<D>(dx, V, W, F, Wc, Gc)) return false;
  ConsistencySums<D> s;
  s.neighbours = static_cast<int>(dx.size());
  for (std::size_t b = 0; b < dx.size(); ++b) {
    s.S0 += Wc[b] * V[b];
    for (int a = 0; a < D; ++a) {
      s.S1[a] += dx[b][a] * Wc[b] * V[b];
      s.G0[a] += Gc[b][a] * V[b];
      for (int c = 0; c < D; ++c) s.G1[a][c] += -dx[b][a] * Gc[b][c] * V[b];
    }
  }
  out = s;
  return true;
}

}  // namespace sphmol::analysis
