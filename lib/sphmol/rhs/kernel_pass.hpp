#pragma once
// Compacts the Verlet list to the pairs inside the kernel support and computes dx_ij, W_ij and
// F_ij = (dW/dr)/r for each, once per RHS evaluation. The only place a kernel is evaluated in the
// RHS, instantiated per kernel type.
#include <cmath>
#include <memory>
#include <string_view>

#include "sphmol/kernels/kernel.hpp"
#include "sphmol/rhs/workspace.hpp"

namespace sphmol {

template <int D>
class KernelPass {
 public:
  virtual ~KernelPass() = default;
  virtual std::string_view kernel_name() const = 0;
  virtual double support() const = 0;  // in units of h
  virtual double value_at_zero(double h) const = 0;
  virtual void apply(const PairList& verlet, Workspace<D>& w) const = 0;
};

template <int D, SphKernel K>
class KernelPassFor final : public KernelPass<D> {
 public:
  std::string_view kernel_name() const override { return K::name; }
  double support() const override { return K::support; }
  double value_at_zero(double h) const override { return K::W(0.0, h); }
  // Kernels follow W(r, h) = W(r/h, 1) / h^D (kernels/kernel.hpp), so the loop evaluates at h = 1,
  // where every division by h folds away, and scales once (checked for every kernel by a unit test).
  // The compaction writes every candidate and advances only for pairs inside the support: no
  // data-dependent branch.
  void apply(const PairList& verlet, Workspace<D>& w) const override {
    const double inv_h = 1.0 / w.h, rc2 = K::support * w.h * K::support * w.h;
    const double w_scale = 1.0 / h_power<D>(w.h), dw_scale = w_scale * inv_h;
    const std::size_t rows = verlet.rows(), cap = verlet.pairs();
    PairList& P = w.pairs;
    P.offset.resize(rows + 1);
    P.j.resize(cap + 1);  // one slot of slack for the last unconditional write
    for (int d = 0; d < D; ++d) w.dx[d].resize(cap + 1);
    w.W.resize(cap + 1);
    w.F.resize(cap + 1);
    w.vfac.resize(cap + 1);
    std::uint32_t* pj = P.j.data();
    double *pW = w.W.data(), *pF = w.F.data(), *pv = w.vfac.data();
    double* pdx[D];
    const double* px[D];
    double period[D], inv_period[D];
    for (int d = 0; d < D; ++d) {
      pdx[d] = w.dx[d].data();
      px[d] = w.x[d].data();
      period[d] = w.domain->period(d);
      inv_period[d] = w.domain->inv_period(d);
    }
    const std::uint32_t* vj = verlet.j.data();
    std::uint32_t k = 0;
    P.offset[0] = 0;
    for (std::size_t i = 0; i < rows; ++i) {
      for (std::uint32_t q = verlet.offset[i]; q < verlet.offset[i + 1]; ++q) {
        const std::uint32_t j = vj[q];
        double r2 = 0.0;
        for (int d = 0; d < D; ++d) {
          double dx = px[d][i] - px[d][j];
          dx -= period[d] * std::nearbyint(dx * inv_period[d]);
          pdx[d][k] = dx;
          r2 += dx * dx;
        }
        const double r = std::sqrt(r2);
        double wv, dw;
        K::eval(r * inv_h, 1.0, wv, dw);
        pj[k] = j;
        pW[k] = wv * w_scale;
        pF[k] = r > 0.0 ? dw * dw_scale / r : 0.0;  // coincident particles exert no gradient
        pv[k] = 1.0;                                 // the wall model, if any, overwrites fluid-wall pairs
        k += r2 < rc2 ? 1u : 0u;
      }
      P.offset[i + 1] = k;
    }
    P.j.resize(k);
  }
};

template <int D>
std::unique_ptr<KernelPass<D>> make_kernel_pass(std::string_view kernel_name);

}  // namespace sphmol
