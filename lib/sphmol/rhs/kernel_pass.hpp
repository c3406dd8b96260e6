#pragma once
// Compacts the Verlet list to the pairs inside the kernel support and computes dx_ij, W_ij and
// F_ij = (dW/dr)/r for each, once per RHS evaluation: for the whole list at once (stored pairs) or one
// row at a time (fused passes, rhs/fused_pair_pass.hpp). The only place a kernel is evaluated in the
// RHS, instantiated per kernel type.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string_view>

#include "sphmol/kernels/kernel.hpp"
#include "sphmol/rhs/pair_row.hpp"
#include "sphmol/rhs/workspace.hpp"

namespace sphmol {

// Separation x_i - x_j with the minimum image, from the workspace positions.
template <int D>
struct PairGeometry {
  const double* px[D] = {};
  double period[D] = {}, inv_period[D] = {};
  bool periodic = false;  // in any direction
  PairGeometry() = default;
  explicit PairGeometry(const Workspace<D>& w) {
    for (int d = 0; d < D; ++d) {
      px[d] = w.x[d].data();
      period[d] = w.domain->period(d);
      inv_period[d] = w.domain->inv_period(d);
      periodic = periodic || w.domain->periodic[d];
    }
  }
  // Periodic = false skips the image shift (it is zero without periodic directions, but not free).
  template <bool Periodic = true>
  double separation(std::size_t i, std::uint32_t j, double (&dx)[D]) const {
    double r2 = 0.0;
    for (int d = 0; d < D; ++d) {
      dx[d] = px[d][i] - px[d][j];
      if constexpr (Periodic) dx[d] -= period[d] * std::nearbyint(dx[d] * inv_period[d]);
      r2 += dx[d] * dx[d];
    }
    return r2;
  }
};

template <int D>
class KernelPass {
 public:
  virtual ~KernelPass() = default;
  virtual std::string_view kernel_name() const = 0;
  virtual double support() const = 0;  // in units of h
  virtual double value_at_zero(double h) const = 0;
  // Per-evaluation constants (h, periods, positions); call before fill_row, once per evaluation.
  virtual void prepare(const Workspace<D>& w) = 0;
  // The whole active list into w.pairs (and dx, W, F, vfac): prepares itself.
  virtual void apply(const PairList& verlet, Workspace<D>& w) = 0;
  // Row i only, into a per-thread buffer; returns the number of pairs in it. Thread-safe after prepare.
  // With compact = false the row keeps every Verlet pair, skin pairs with W = F = 0 included (for
  // terms that add nothing for them, PairTerm::zero_beyond_support; every kernel is exactly zero
  // beyond its support, tested), and the compaction stage is skipped.
  virtual std::uint32_t fill_row(const PairList& verlet, std::size_t i, RowBuffer<D>& out, bool compact) const = 0;
  // F_k = (dW/dr)/r at separations r2[k], k < n, for a constant h (the separations' geometry is
  // geometry()): the same numbers fill_row gives a pair at that r2. For terms that evaluate their
  // pairs themselves (PairTerm::pair_records). False from a pass whose F depends on the pair (variable h).
  virtual bool uniform_h() const { return false; }
  virtual void gradient_factors(const double* r2, double* F, std::uint32_t n) const {}
  virtual const PairGeometry<D>& geometry() const = 0;
  // Number of active pairs in the Verlet list at the workspace's positions (prepares itself).
  virtual std::size_t count_active(const PairList& verlet, const Workspace<D>& w) = 0;
};

// Both ways of running a kernel pass over the Verlet list, for a Derived that says which pairs are
// active and evaluates W and F for one (active(i, j, r2), eval(i, j, r2, W, F), using geometry_):
// apply() compacts the whole list, fill_row() one row. Rows run in parallel in apply(): a first pass
// counts each row's pairs inside the support, a prefix sum places the rows, and the second pass fills
// them, so the active list stays one contiguous CSR whatever the thread count and every row is
// written by one thread.
template <int D, SphKernel K, class Derived>
class KernelPassRows : public KernelPass<D> {
 public:
  std::string_view kernel_name() const override { return K::name; }
  double support() const override { return K::support; }
  const PairGeometry<D>& geometry() const final { return geometry_; }
  double value_at_zero(double h) const override { return K::W(0.0, h); }

  void apply(const PairList& verlet, Workspace<D>& w) final {
    this->prepare(w);
    const long rows = static_cast<long>(verlet.rows());
    PairList& P = w.pairs;
    P.offset.resize(static_cast<std::size_t>(rows) + 1);
    std::uint32_t* po = P.offset.data();
    po[0] = 0;
    count_rows(verlet, po + 1);
    w.size_active_pairs(static_cast<std::size_t>(rows));
    double* pdx[D];
    for (int d = 0; d < D; ++d) pdx[d] = w.dx[d].data();
#pragma omp parallel for schedule(static)
    for (long i = 0; i < rows; ++i) {
      const std::uint32_t k = po[i];
      double* dxk[D];
      for (int d = 0; d < D; ++d) dxk[d] = pdx[d] + k;
      fill(verlet, static_cast<std::size_t>(i), P.j.data() + k, dxk, w.W.data() + k, w.F.data() + k,
                  w.vfac.data() + k);
    }
  }

  std::size_t count_active(const PairList& verlet, const Workspace<D>& w) final {
    this->prepare(w);
    std::vector<std::uint32_t> counts(verlet.rows());
    count_rows(verlet, counts.data());
    std::size_t total = 0;
    for (const auto c : counts) total += c;
    return total;
  }

  std::uint32_t fill_row(const PairList& verlet, std::size_t i, RowBuffer<D>& out, bool compact) const final {
    const std::uint32_t q0 = verlet.offset[i], n = verlet.offset[i + 1] - q0;
    out.reserve(n);
    return geometry_.periodic ? staged<true>(verlet.j.data() + q0, n, i, out, compact)
                              : staged<false>(verlet.j.data() + q0, n, i, out, compact);
  }

 protected:
  PairGeometry<D> geometry_;

 private:
  // One row in three stages: (A) the separations of all its Verlet pairs (gathers of x_j), (B) the
  // kernel for all of them over contiguous arrays, with no branch and no gather, which the compiler
  // vectorises for a branch-free kernel (a pair beyond the support costs an evaluation, not a
  // misprediction), (C) the active pairs moved to the front in place (slot k <= q), unless the row's
  // terms take the skin pairs with their zero W and F (compact = false: about a third of the pass).
  template <bool Periodic>
  std::uint32_t staged(const std::uint32_t* vj, std::uint32_t n, std::size_t i, RowBuffer<D>& b, bool compact) const {
    const auto* self = static_cast<const Derived*>(this);
    std::uint32_t* __restrict pj = b.j.data();
    double* __restrict pr2 = b.r2.data();
    double* __restrict pW = b.W.data();
    double* __restrict pF = b.F.data();
    double* __restrict pv = b.vfac.data();
    double* pdx[D];
    for (int d = 0; d < D; ++d) pdx[d] = b.dx[d].data();
    for (std::uint32_t q = 0; q < n; ++q) {
      const std::uint32_t j = vj[q];
      double dx[D];
      pr2[q] = geometry_.template separation<Periodic>(i, j, dx);
      pj[q] = j;
      for (int d = 0; d < D; ++d) pdx[d][q] = dx[d];
    }
    for (std::uint32_t q = 0; q < n; ++q) self->eval(i, pj[q], pr2[q], pW[q], pF[q]);
    if (!compact) {
      std::fill(pv, pv + n, 1.0);
      return n;
    }
    std::uint32_t k = 0;
    for (std::uint32_t q = 0; q < n; ++q) {
      const bool on = self->active(i, pj[q], pr2[q]);
      pj[k] = pj[q];
      for (int d = 0; d < D; ++d) pdx[d][k] = pdx[d][q];
      pW[k] = pW[q];
      pF[k] = pF[q];
      pv[k] = 1.0;  // the wall model, if any, overwrites fluid-wall pairs
      k += on ? 1u : 0u;
    }
    return k;
  }

  // Each row's number of active pairs into counts[i].
  void count_rows(const PairList& verlet, std::uint32_t* counts) const {
    const long rows = static_cast<long>(verlet.rows());
    const auto* self = static_cast<const Derived*>(this);
    const std::uint32_t* vj = verlet.j.data();
    const std::uint32_t* vo = verlet.offset.data();
#pragma omp parallel for schedule(static)
    for (long i = 0; i < rows; ++i) {
      std::uint32_t count = 0;
      for (std::uint32_t q = vo[i]; q < vo[i + 1]; ++q) {
        double dx[D];
        const auto ii = static_cast<std::size_t>(i);
        count += self->active(ii, vj[q], geometry_.separation(ii, vj[q], dx)) ? 1u : 0u;
      }
      counts[i] = count;
    }
  }

  // Row i of the stored list: only active pairs are written, since the next row follows at once.
  std::uint32_t fill(const PairList& verlet, std::size_t i, std::uint32_t* pj, double* const (&pdx)[D], double* pW,
                     double* pF, double* pv) const {
    return geometry_.periodic ? fill<true>(verlet, i, pj, pdx, pW, pF, pv) : fill<false>(verlet, i, pj, pdx, pW, pF, pv);
  }
  template <bool Periodic>
  std::uint32_t fill(const PairList& verlet, std::size_t i, std::uint32_t* pj, double* const (&pdx)[D], double* pW,
                     double* pF, double* pv) const {
    const auto* self = static_cast<const Derived*>(this);
    std::uint32_t k = 0;
    for (std::uint32_t q = verlet.offset[i]; q < verlet.offset[i + 1]; ++q) {
      const std::uint32_t j = verlet.j[q];
      double dx[D];
      const double r2 = geometry_.template separation<Periodic>(i, j, dx);
      if (!self->active(i, j, r2)) continue;
      self->eval(i, j, r2, pW[k], pF[k]);
      pj[k] = j;
      for (int d = 0; d < D; ++d) pdx[d][k] = dx[d];
      pv[k] = 1.0;  // the wall model, if any, overwrites fluid-wall pairs
      ++k;
    }
    return k;
  }
};

template <int D, SphKernel K>
class KernelPassFor final : public KernelPassRows<D, K, KernelPassFor<D, K>> {
 public:
  // Kernels follow W(r, h) = W(r/h, 1) / h^D (kernels/kernel.hpp), so the loop evaluates at h = 1,
  // where every division by h folds away, and scales once (checked for every kernel by a unit test).
  void prepare(const Workspace<D>& w) override {
    this->geometry_ = PairGeometry<D>(w);
    inv_h_ = 1.0 / w.h;
    rc2_ = K::support * w.h * K::support * w.h;
    w_scale_ = 1.0 / h_power<D>(w.h);
    f_scale_ = w_scale_ * inv_h_ * inv_h_;  // F = (dW/dr)/r scales as h^-(D+2)
  }
  bool uniform_h() const override { return true; }
  void gradient_factors(const double* __restrict r2, double* __restrict F, std::uint32_t n) const override {
    for (std::uint32_t k = 0; k < n; ++k) {
      double wv, f;
      kernel_unit_over_r<K>(std::sqrt(r2[k]) * inv_h_, wv, f);
      F[k] = f * f_scale_;
    }
  }
  bool active(std::size_t, std::uint32_t, double r2) const { return r2 < rc2_; }
  void eval(std::size_t, std::uint32_t, double r2, double& W, double& F) const {
    double wv, f;
    kernel_unit_over_r<K>(std::sqrt(r2) * inv_h_, wv, f);
    W = wv * w_scale_;
    // No select on r = 0, so that the loop vectorises: coincident particles have dx = 0 and exert no
    // force; F there is the kernel's limit of (dW/dr)/r (0 for a kernel without the closed form).
    F = f * f_scale_;
  }

 private:
  double inv_h_ = 0.0, rc2_ = 0.0, w_scale_ = 0.0, f_scale_ = 0.0;
};

template <int D>
std::unique_ptr<KernelPass<D>> make_kernel_pass(std::string_view kernel_name);

}  // namespace sphmol
