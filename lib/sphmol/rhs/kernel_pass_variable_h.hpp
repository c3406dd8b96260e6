#pragma once
// Kernel pass for a variable smoothing length (Niedoba 2012, §2.2.5): each pair uses the
// symmetrised h_ij = (h_i + h_j)/2 (Niedoba 2012, eq 2.69), so W_ij = W_ji and grad_i W_ij =
// -grad_j W_ji and pair forces stay antisymmetric; a pair is active when r_ij < kappa h_ij (Niedoba
// 2012, eq 2.79). Chosen once per scene instead of KernelPassFor: the constant-h loop carries no
// per-pair h.
#include "sphmol/rhs/kernel_pass.hpp"

namespace sphmol {

template <int D, SphKernel K>
class KernelPassVariableH final : public KernelPassRows<D, K, KernelPassVariableH<D, K>> {
 public:
  void prepare(const Workspace<D>& w) override {
    this->geometry_ = PairGeometry<D>(w);
    hs_ = w.hs.data();
  }
  bool active(std::size_t i, std::uint32_t j, double r2) const {
    const double rc = K::support * (0.5 * (hs_[i] + hs_[j]));  // Niedoba 2012, eq 2.79, h_ij of eq 2.69
    return r2 < rc * rc;
  }
  void eval(std::size_t i, std::uint32_t j, double r2, double& W, double& F) const {
    const double hij = 0.5 * (hs_[i] + hs_[j]), inv_h = 1.0 / hij;
    const double w_scale = 1.0 / h_power<D>(hij);
    double wv, f;
    kernel_unit_over_r<K>(std::sqrt(r2) * inv_h, wv, f);
    W = wv * w_scale;
    F = r2 > 0.0 ? f * w_scale * inv_h * inv_h : 0.0;
  }

 private:
  const double* hs_ = nullptr;
};

template <int D>
std::unique_ptr<KernelPass<D>> make_variable_h_kernel_pass(std::string_view kernel_name);

}  // namespace sphmol
