#pragma once
// Kernel pass for a variable smoothing length (seed 003 §2.2.5): each pair uses the symmetrised
// h_ij = (h_i + h_j)/2 (seed 003 eq 2.69), so W_ij = W_ji and grad_i W_ij = -grad_j W_ji and pair
// forces stay antisymmetric; a pair is active when r_ij < kappa h_ij (seed 003 eq 2.79). Chosen once
// per scene instead of KernelPassFor: the constant-h loop carries no per-pair h.
#include "sphmol/rhs/kernel_pass.hpp"

namespace sphmol {

template <int D, SphKernel K>
class KernelPassVariableH final : public KernelPass<D> {
 public:
  std::string_view kernel_name() const override { return K::name; }
  double support() const override { return K::support; }
  double value_at_zero(double h) const override { return K::W(0.0, h); }
  // Rows in parallel as in KernelPassFor: count each row's active pairs, prefix-sum the row starts,
  // then fill; every row is written by one thread, the list is the same for any thread count.
  void apply(const PairList& verlet, Workspace<D>& w) const override {
    const long rows = static_cast<long>(verlet.rows());
    PairList& P = w.pairs;
    const double* hs = w.hs.data();
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
    auto active = [&](std::size_t i, std::uint32_t j, double r2) {
      const double rc = K::support * (0.5 * (hs[i] + hs[j]));  // seed 003 eq 2.79, h_ij of eq 2.69
      return r2 < rc * rc;
    };

    P.offset.resize(static_cast<std::size_t>(rows) + 1);
    std::uint32_t* po = P.offset.data();
    po[0] = 0;
#pragma omp parallel for schedule(static)
    for (long i = 0; i < rows; ++i) {
      std::uint32_t count = 0;
      for (std::uint32_t q = vo[i]; q < vo[i + 1]; ++q) {
        double dx[D];
        count += active(static_cast<std::size_t>(i), vj[q], separation(static_cast<std::size_t>(i), vj[q], dx)) ? 1u : 0u;
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
        if (!active(static_cast<std::size_t>(i), j, r2)) continue;
        const double hij = 0.5 * (hs[i] + hs[j]), inv_h = 1.0 / hij;
        const double w_scale = 1.0 / h_power<D>(hij);
        const double r = std::sqrt(r2);
        double wv, dw;
        K::eval(r * inv_h, 1.0, wv, dw);
        pj[k] = j;
        for (int d = 0; d < D; ++d) pdx[d][k] = dx[d];
        pW[k] = wv * w_scale;
        pF[k] = r > 0.0 ? dw * w_scale * inv_h / r : 0.0;
        pv[k] = 1.0;
        ++k;
      }
    }
  }
};

template <int D>
std::unique_ptr<KernelPass<D>> make_variable_h_kernel_pass(std::string_view kernel_name);

}  // namespace sphmol
