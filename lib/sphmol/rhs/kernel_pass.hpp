#pragma once
// Computes W_ij and F_ij = (dW/dr)/r for every listed pair, once per RHS evaluation. The only
// place a kernel is evaluated in the RHS, instantiated per kernel type.
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
  virtual void apply(Workspace<D>& w) const = 0;
};

template <int D, SphKernel K>
class KernelPassFor final : public KernelPass<D> {
 public:
  std::string_view kernel_name() const override { return K::name; }
  double support() const override { return K::support; }
  double value_at_zero(double h) const override { return K::W(0.0, h); }
  void apply(Workspace<D>& w) const override {
    const auto& P = *w.pairs;
    w.W.resize(P.pairs());
    w.F.resize(P.pairs());
    const double h = w.h;
    const std::size_t rows = P.rows();
    for (std::size_t i = 0; i < rows; ++i) {
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
        const std::uint32_t j = P.j[k];
        double r2 = 0.0;
        for (int d = 0; d < D; ++d) {
          const double dx = w.separation(d, i, j);
          r2 += dx * dx;
        }
        const double r = std::sqrt(r2);
        double wv, dw;
        K::eval(r, h, wv, dw);
        w.W[k] = wv;
        w.F[k] = r > 0.0 ? dw / r : 0.0;  // coincident particles exert no gradient
      }
    }
  }
};

template <int D>
std::unique_ptr<KernelPass<D>> make_kernel_pass(std::string_view kernel_name);

}  // namespace sphmol
