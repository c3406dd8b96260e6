#pragma once
// Ghost pressure under a body force g (gravity), run right after the EOS. A mirrored density copies
// the source's pressure p_i to the image; in a column at rest that is wrong by the hydrostatic jump
// between the two positions: below the bottom wall the image must carry p_i + rho_i g.(x_g - x_i)
// (= p_i + 2 rho_i g d for a source at height d; g points down), as the continuation of
// p = p0 + rho g.x through the wall would. With the copied value the wall row is short of support by
// 2 rho g d per image and the column sinks through the bottom (hydrostatic case at 20 across:
// blow-up at t = 1.7 s). This is the ghost counterpart of the extrapolated wall pressure of Adami et
// al. (2012) eq. 27 (boundary/wall_pressure_extrapolated.hpp). The image density follows from the
// inverse EOS, so that p_g / rho_g^2 in the momentum equation is consistent with the EOS. Side walls
// (g.(x_g - x_i) = 0) keep the copied values.
#include <array>
#include <functional>

#include "sphmol/boundary/ghost_particles.hpp"
#include "sphmol/physics/body_force.hpp"
#include "sphmol/rhs/term.hpp"

namespace sphmol {

template <int D>
class GhostHydrostaticPressure final : public Term<D> {
 public:
  GhostHydrostaticPressure(const GhostGenerator<D>* gen, const std::array<double, D>& g, double ramp,
                           std::function<double(double)> density_of_pressure)
      : gen_(gen), g_(g), ramp_(ramp), rho_of_p_(std::move(density_of_pressure)) {}
  std::string_view name() const override { return "ghost_hydrostatic_pressure"; }
  void apply(Workspace<D>& w) const override {
    const auto& src = gen_->sources();
    const std::size_t b = gen_->base();
    const double f = body_force_ramp_factor(w.t, ramp_);
    for (std::size_t g = 0; g < src.size(); ++g) {
      const std::size_t i = src[g];
      double gr = 0.0;
      for (int d = 0; d < D; ++d) gr += f * g_[d] * (w.x[d][b + g] - w.x[d][i]);
      if (gr == 0.0) continue;
      w.p[b + g] = w.p[i] + w.rho[i] * gr;
      w.rho[b + g] = rho_of_p_(w.p[b + g]);
    }
  }

 private:
  const GhostGenerator<D>* gen_;
  std::array<double, D> g_;
  double ramp_;
  std::function<double(double)> rho_of_p_;
};

}  // namespace sphmol
