#pragma once
// Constant body force per unit mass (gravity, or the driving pressure gradient of Poiseuille flow),
// optionally ramped in smoothly over `ramp` seconds: g(t) = g (1 - cos(pi t / ramp)) / 2 for t < ramp.
// Switching gravity on at once sends a pressure wave through a column that starts at uniform density;
// a ramp much longer than the acoustic crossing time lets it compress quasi-statically.
#include <array>
#include <cmath>
#include <numbers>

#include "sphmol/rhs/term.hpp"

namespace sphmol {

inline double body_force_ramp_factor(double t, double ramp) {
  return (ramp > 0.0 && t < ramp) ? 0.5 * (1.0 - std::cos(std::numbers::pi * t / ramp)) : 1.0;
}

template <int D>
class BodyForce final : public Term<D> {
 public:
  explicit BodyForce(const std::array<double, D>& g, double ramp = 0.0) : g_(g), ramp_(ramp) {}
  std::string_view name() const override { return "body_force"; }
  bool runs_in_team() const override { return true; }  // worksharing loops (Term::runs_in_team)
  void apply(Workspace<D>& w) const override {
    const double f = body_force_ramp_factor(w.t, ramp_);
    for (int d = 0; d < D; ++d) {
#pragma omp for schedule(static) nowait
      for (std::size_t i = 0; i < w.n_fluid; ++i) w.dvdt[d][i] += f * g_[d];
    }
#pragma omp barrier
  }

 private:
  std::array<double, D> g_;
  double ramp_;
};

}  // namespace sphmol
