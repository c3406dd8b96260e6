#include "sphmol/cases/shock_tube/shock_tube_wall_clearance.hpp"

#include <algorithm>
#include <stdexcept>

namespace sphmol {

namespace {

// Speeds of the outermost waves towards the left and the right end (> 0 for states at rest: a left
// shock or fan head moves left into the left gas, Toro 2009 eqs 4.52, 4.55; the right ones right).
std::array<double, 2> outward_speeds(const ExactRiemannSolver& exact) {
  if (exact.left().u != 0.0 || exact.right().u != 0.0)
    throw std::invalid_argument("shock_tube_clearance: the states must be at rest (a moving state disturbs its end wall at t = 0)");
  const RiemannWaves w = exact.wave_speeds();
  return {-w.left_head, w.right_head};
}

}  // namespace

ShockTubeClearance shock_tube_clearance(const ExactRiemannSolver& exact, double half_length, const std::array<double, 2>& reach) {
  const auto speed = outward_speeds(exact);
  const RiemannWaves w = exact.wave_speeds();
  ShockTubeClearance c{0.0, 0, 0.0, false};
  for (int side = 0; side < 2; ++side) {
    const auto k = static_cast<std::size_t>(side);
    const double t = (half_length - reach[k]) / speed[k];
    if (side == 0 || t < c.t_clear) c = {t, side, speed[k], side == 0 ? w.left_is_shock : w.right_is_shock};
  }
  return c;
}

double shock_tube_length_for(const ExactRiemannSolver& exact, double t, const std::array<double, 2>& reach) {
  const auto speed = outward_speeds(exact);
  return 2.0 * std::max(speed[0] * t + reach[0], speed[1] * t + reach[1]);
}

}  // namespace sphmol
