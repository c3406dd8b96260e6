#pragma once
// The discrete second moment of the Morris, Fox & Zhu (1997) viscous sum per fluid particle,
//   M_i = -(1/D) sum_j (m_j / rho_j) F_ij r_ij^2 * r_ij^2 / (r_ij^2 + eta^2),   eta^2 = 0.01 h^2,
// the same sum `laplacian_correction: moment` accumulates inside each viscous row
// (physics/morris_viscosity.hpp). In the continuum M = 1 in every dimension; on particles it is the
// factor by which the Morris Laplacian of a quadratic field falls short. The pair-symmetric correction
// (`moment_symmetric`) needs M_j of every neighbour j while summing row i, so the moments are a pass
// of their own, written here before the viscous rows read them (a term that feeds neighbours ends a
// fused pass, rhs/pair_pass_plan.hpp). Wall particles get no moment: their rows are not summed.
#include <memory>
#include <vector>

#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

// M_i per fluid particle (workspace index): written by MorrisMoment, read at neighbours by
// MorrisViscosity<D, LaplacianCorrection::moment_symmetric>.
using MorrisMomentField = std::vector<double>;

template <int D>
class MorrisMoment final : public PairTermFor<D, MorrisMoment<D>> {
 public:
  explicit MorrisMoment(std::shared_ptr<MorrisMomentField> moment) : moment_(std::move(moment)) {}
  std::string_view name() const override { return "morris_moment"; }
  bool feeds_neighbours() const override { return true; }
  void prepare(Workspace<D>& w) const override { moment_->resize(w.n_fluid); }
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const auto& m = w.particles->mass;
    const double eta2 = 0.01 * w.h * w.h;
    double s = 0.0;  // sum_j V_j F_ij r^4 / (r^2 + eta^2), negative
    for (std::uint32_t k = 0; k < r.n; ++k) {
      const std::uint32_t j = r.j[k];
      double r2 = 0.0;
      for (int d = 0; d < D; ++d) r2 += r.dx[d][k] * r.dx[d][k];
      s += m[j] / w.rho[j] * r.F[k] * r2 / (r2 + eta2) * r2;
    }
    // A particle with no neighbours has no Laplacian to correct: M = 1 leaves its pairs (there are
    // none) alone and keeps 2 / (M_i + M_j) finite.
    (*moment_)[i] = s < 0.0 ? -s / static_cast<double>(D) : 1.0;
  }

 private:
  std::shared_ptr<MorrisMomentField> moment_;
};

}  // namespace sphmol
