#pragma once
// Equation of state p = c^2 rho (Morris et al. 1997; seed 002 eq 20, seed 000 eq 126): an
// artificially compressible fluid whose sound speed c is chosen so that density varies ~1 %.
#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class LinearEos final : public Term<D> {
 public:
  explicit LinearEos(double sound_speed) : c2_(sound_speed * sound_speed) {}
  std::string_view name() const override { return "eos_linear"; }
  void apply(Workspace<D>& w) const override {
    for (std::size_t i = 0; i < w.n; ++i) w.p[i] = c2_ * w.rho[i];
  }

 private:
  double c2_;
};

}  // namespace sphmol
