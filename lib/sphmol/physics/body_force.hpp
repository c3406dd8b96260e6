#pragma once
// Constant body force per unit mass (gravity, or the driving pressure gradient of Poiseuille flow).
#include <array>

#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class BodyForce final : public Term<D> {
 public:
  explicit BodyForce(const std::array<double, D>& g) : g_(g) {}
  std::string_view name() const override { return "body_force"; }
  void apply(Workspace<D>& w) const override {
    for (int d = 0; d < D; ++d)
      for (std::size_t i = 0; i < w.n_fluid; ++i) w.dvdt[d][i] += g_[d];
  }

 private:
  std::array<double, D> g_;
};

}  // namespace sphmol
