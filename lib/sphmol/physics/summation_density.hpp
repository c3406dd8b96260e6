#pragma once
// Summation density, seed 002 eq 11 / seed 000 eq 100: rho_i = sum_j m_j W_ij, including i itself.
// Wall particles keep their rest density (their rows list only fluid neighbours, so a sum there
// would be truncated).
#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class SummationDensity final : public Term<D> {
 public:
  std::string_view name() const override { return "summation_density"; }
  void apply(Workspace<D>& w) const override {
    const auto& P = w.pairs;
    const auto& m = w.particles->mass;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < w.n_fluid; ++i) {
      double rho = m[i] * w.W0;
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) rho += m[P.j[k]] * w.W[k];
      w.rho[i] = rho;
    }
  }
};

}  // namespace sphmol
