#pragma once
// XSPH position update, Vukčević et al. 2012, eq 21 (Vukčević 2012, eq 127):
//   dx_i/dt = v_i - eps sum_j (m_j/rho_j) v_ij W_ij,   v_ij = v_i - v_j
// The plain dx/dt = v is set by the RHS before the terms run; this term adds the correction.
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

template <int D>
class Xsph final : public PairTermFor<D, Xsph<D>> {
 public:
  explicit Xsph(double epsilon) : eps_(epsilon) {}
  std::string_view name() const override { return "xsph"; }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    double c[D] = {};
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      const double s = m[j] / w.rho[j] * r.W[k];
      for (int d = 0; d < D; ++d) c[d] += s * (w.v[d][i] - w.v[d][j]);
    }
    for (int d = 0; d < D; ++d) w.dxdt[d][i] -= eps_ * c[d];
  }

 private:
  double eps_;
};

}  // namespace sphmol
