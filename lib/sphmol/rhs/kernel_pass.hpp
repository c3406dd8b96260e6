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
  // Rows run in parallel: a first pass counts each row's pairs inside the support, a prefix sum
  // places the rows, and the second pass fills them, so the active list stays one contiguous CSR
  // whatever the thread count and every row is written by one thread.
  void apply(const PairList& verlet, Workspace<D>& w) const override {
    const double inv_h = 1.0 / w.h, rc2 = K::support * w.h * K::support * w.h;
    const double w_scale = 1.0 / h_power<D>(w.h), dw_scale = w_scale * inv_h;
    const long rows = static_cast<long>(verlet.rows());
    PairList& P = w.pairs;
    const double* px[D];
    double period[D], inv_period[D];
    for (int d = 0; d < D; ++d) {
      px[d] = w.x[d].data();
      period[d] = w.domain->period(d);
      inv_period[d] = w.domain->inv_period(d);
    }
    const std::uint32_t* vj = verlet.j.data();
    const std::uint32_t* vo = verlet.offset.data();
    auto separation = [&](std::size_t i, std::uint32_t j, double (&dx)[D]) {
      double r2 = 0.0;
      for (int d = 0; d < D; ++d) {
        dx[d] = px[d][i] - px[d][j];
        dx[d] -= period[d] * std::nearbyint(dx[d] * inv_period[d]);
        r2 += dx[d] * dx[d];
      }
      return r2;
    };

    P.offset.resize(static_cast<std::size_t>(rows) + 1);
    std::uint32_t* po = P.offset.data();
    po[0] = 0;
#pragma omp parallel for schedule(static)
    for (long i = 0; i < rows; ++i) {
      std::uint32_t count = 0;
      for (std::uint32_t q = vo[i]; q < vo[i + 1]; ++q) {
        double dx[D];
        count += separation(static_cast<std::size_t>(i), vj[q], dx) < rc2 ? 1u : 0u;
      }
      po[i + 1] = count;
    }
    w.size_active_pairs(static_cast<std::size_t>(rows));
    std::uint32_t* pj = P.j.data();
    double *pW = w.W.data(), *pF = w.F.data(), *pv = w.vfac.data();
    double* pdx[D];
    for (int d = 0; d < D; ++d) pdx[d] = w.dx[d].data();

#pragma omp parallel for schedule(static)
    for (long i = 0; i < rows; ++i) {
      std::uint32_t k = po[i];
      for (std::uint32_t q = vo[i]; q < vo[i + 1]; ++q) {
        const std::uint32_t j = vj[q];
        double dx[D];
        const double r2 = separation(static_cast<std::size_t>(i), j, dx);
        if (r2 >= rc2) continue;
        const double r = std::sqrt(r2);
        double wv, dw;
        K::eval(r * inv_h, 1.0, wv, dw);
        pj[k] = j;
        for (int d = 0; d < D; ++d) pdx[d][k] = dx[d];
        pW[k] = wv * w_scale;
        pF[k] = r > 0.0 ? dw * dw_scale / r : 0.0;  // coincident particles exert no gradient
        pv[k] = 1.0;                                 // the wall model, if any, overwrites fluid-wall pairs
        ++k;
      }
    }
  }
};

template <int D>
std::unique_ptr<KernelPass<D>> make_kernel_pass(std::string_view kernel_name);

}  // namespace sphmol
