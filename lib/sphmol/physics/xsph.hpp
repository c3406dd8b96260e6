#pragma once
// XSPH position update, seed 002 eq 21 (seed 000 eq 127):
//   dx_i/dt = v_i - eps sum_j (m_j/rho_j) v_ij W_ij,   v_ij = v_i - v_j
// The plain dx/dt = v is set by the RHS before the terms run; this term adds the correction.
#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class Xsph final : public Term<D> {
 public:
  explicit Xsph(double epsilon) : eps_(epsilon) {}
  std::string_view name() const override { return "xsph"; }
  void apply(Workspace<D>& w) const override {
    const auto& P = w.pairs;
    const auto& m = w.particles->mass;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < w.n_fluid; ++i) {
      double c[D] = {};
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
        const std::uint32_t j = P.j[k];
        const double s = m[j] / w.rho[j] * w.W[k];
        for (int d = 0; d < D; ++d) c[d] += s * (w.v[d][i] - w.v[d][j]);
      }
      for (int d = 0; d < D; ++d) w.dxdt[d][i] -= eps_ * c[d];
    }
  }

 private:
  double eps_;
};

}  // namespace sphmol
