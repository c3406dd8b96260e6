#pragma once
// Normalised summation density, Niedoba 2012, eq 2.58:
//   rho_i = sum_j m_j W_ij / sum_j (m_j / rho_j) W_ij        (both sums include j = i)
// The rho_j of the denominator must come from the same state for the RHS to be a function of y
// alone, so they are the plain summation densities (Vukčević 2012, eq 100) of a first pass; near a
// free surface or a density jump both sums miss the same neighbours and the deficit largely cancels
// (the "edge effect" Niedoba 2012, §3.3 mentions). Wall particles keep their rest density.
#include <vector>

#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class NormalisedSummationDensity final : public Term<D> {
 public:
  std::string_view name() const override { return "normalised_summation_density"; }
  bool reads_stored_pairs() const override { return true; }
  void apply(Workspace<D>& w) const override {
    const auto& P = w.pairs;
    const auto& m = w.particles->mass;
    raw_.assign(w.rho.begin(), w.rho.end());  // walls: their fixed density
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < w.n_fluid; ++i) {
      double rho = m[i] * self_W(w, i);
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) rho += m[P.j[k]] * w.W[k];
      raw_[i] = rho;
    }
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < w.n_fluid; ++i) {
      const double w0 = self_W(w, i);
      double num = m[i] * w0, den = m[i] / raw_[i] * w0;
      for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
        const std::uint32_t j = P.j[k];
        num += m[j] * w.W[k];
        den += m[j] / raw_[j] * w.W[k];
      }
      w.rho[i] = num / den;
    }
  }

 private:
  // W(0, h_i) by the scaling W(0, h) = W(0, h0) (h0/h)^D, exact for every kernel (kernels/kernel.hpp).
  static double self_W(const Workspace<D>& w, std::size_t i) {
    double s = w.h / w.hs[i], f = 1.0;
    for (int d = 0; d < D; ++d) f *= s;
    return w.W0 * f;
  }
  mutable std::vector<double> raw_;
};

}  // namespace sphmol
