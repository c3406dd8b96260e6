#include "sphmol/reference/taylor_green.hpp"

#include <cmath>
#include <numbers>

namespace sphmol {

namespace {
constexpr double two_pi = 2.0 * std::numbers::pi;
}

double TaylorGreenVortex::decay_rate() const { return -8.0 * std::numbers::pi * std::numbers::pi * nu(); }

double TaylorGreenVortex::u(double x, double y, double t) const {
  return -U * std::exp(decay_rate() * t) * std::cos(two_pi * x) * std::sin(two_pi * y);
}

double TaylorGreenVortex::v(double x, double y, double t) const {
  return U * std::exp(decay_rate() * t) * std::sin(two_pi * x) * std::cos(two_pi * y);
}

double TaylorGreenVortex::pressure(double x, double y, double t) const {
  return -0.25 * rho * U * U * std::exp(2.0 * decay_rate() * t) * (std::cos(2.0 * two_pi * x) + std::cos(2.0 * two_pi * y));
}

double TaylorGreenVortex::kinetic_energy(double t) const {
  // <cos^2 sin^2> = 1/4 over the unit square for each component: rho/2 * 2 * U^2 e^{2bt}/4.
  return 0.25 * rho * U * U * std::exp(2.0 * decay_rate() * t);
}

}  // namespace sphmol
