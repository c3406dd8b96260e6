#pragma once
// Largest displacement of any fluid particle from its initial position, checked at every RHS
// evaluation (so every step and stage, not only output times). A term with no effect on the RHS;
// the hydrostatic case appends it. Positions are those the RHS sees (not wrapped in walled directions).
#include <algorithm>
#include <cmath>
#include <memory>

#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class DriftMonitor final : public Term<D> {
 public:
  DriftMonitor(const Particles<D>& initial, std::shared_ptr<double> max_drift) : max_(std::move(max_drift)) {
    for (int d = 0; d < D; ++d) x0_[d].assign(initial.x[d].begin(), initial.x[d].begin() + initial.n_fluid);
  }
  std::string_view name() const override { return "drift_monitor"; }
  void apply(Workspace<D>& w) const override {
    double m2 = 0.0;
    for (std::size_t i = 0; i < w.n_fluid; ++i) {
      double r2 = 0.0;
      for (int d = 0; d < D; ++d) {
        const double dx = w.domain->min_image(d, w.x[d][i] - x0_[d][w.order ? w.order[i] : i]);
        r2 += dx * dx;
      }
      m2 = std::max(m2, r2);
    }
    *max_ = std::max(*max_, std::sqrt(m2));
  }

 private:
  std::array<std::vector<double>, D> x0_;
  std::shared_ptr<double> max_;
};

}  // namespace sphmol
