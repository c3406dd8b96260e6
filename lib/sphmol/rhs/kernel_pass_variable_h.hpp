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
  void apply(const PairList& verlet, Workspace<D>& w) const override {
    const std::size_t rows = verlet.rows(), cap = verlet.pairs();
    PairList& P = w.pairs;
    P.offset.resize(rows + 1);
    P.j.resize(cap + 1);
    for (int d = 0; d < D; ++d) w.dx[d].resize(cap + 1);
    w.W.resize(cap + 1);
    w.F.resize(cap + 1);
    w.vfac.resize(cap + 1);
    std::uint32_t* pj = P.j.data();
    double *pW = w.W.data(), *pF = w.F.data(), *pv = w.vfac.data();
    const double* hs = w.hs.data();
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
        const double hij = 0.5 * (hs[i] + hs[j]), inv_h = 1.0 / hij;
        const double w_scale = 1.0 / h_power<D>(hij), rc = K::support * hij;
        const double r = std::sqrt(r2);
        double wv, dw;
        K::eval(r * inv_h, 1.0, wv, dw);
        pj[k] = j;
        pW[k] = wv * w_scale;
        pF[k] = r > 0.0 ? dw * w_scale * inv_h / r : 0.0;
        pv[k] = 1.0;
        k += r2 < rc * rc ? 1u : 0u;
      }
      P.offset[i + 1] = k;
    }
    P.j.resize(k);
  }
};

template <int D>
std::unique_ptr<KernelPass<D>> make_variable_h_kernel_pass(std::string_view kernel_name);

}  // namespace sphmol
