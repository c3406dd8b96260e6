#pragma once
// Summation density, Vukčević et al. 2012, eq 11 / Vukčević 2012, eq 100: rho_i = sum_j m_j W_ij,
// including i itself. Wall particles keep their rest density (their rows list only fluid
// neighbours, so a sum there would be truncated).
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

template <int D>
class SummationDensity final : public PairTermFor<D, SummationDensity<D>> {
 public:
  std::string_view name() const override { return "summation_density"; }
  bool feeds_neighbours() const override { return true; }  // every later term reads rho_j
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    double rho = m[i] * w.W0;
    for (std::uint32_t k = 0; k < r.n; ++k) rho += m[r.j[k]] * r.W[k];
    w.rho[i] = rho;
  }
};

}  // namespace sphmol
