#include "sphmol/reference/abc_flow.hpp"

#include <cmath>
#include <numbers>

namespace sphmol {

double AbcFlow::wavenumber() const { return 2.0 * std::numbers::pi / L; }

double AbcFlow::decay_rate() const {
  const double k = wavenumber();
  return nu * k * k;
}

std::array<double, 3> AbcFlow::velocity(double x, double y, double z, double t) const {
  const double k = wavenumber();
  const double f = std::exp(-decay_rate() * t);
  return {f * (A * std::sin(k * z) + C * std::cos(k * y)), f * (B * std::sin(k * x) + A * std::cos(k * z)),
          f * (C * std::sin(k * y) + B * std::cos(k * x))};
}

double AbcFlow::pressure(double x, double y, double z, double t) const {
  const auto u = velocity(x, y, z, t);
  return p0 - 0.5 * rho * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
}

double AbcFlow::kinetic_energy(double t) const {
  // Each squared component averages to the half sum of its two squared amplitudes (the cross terms,
  // products of functions of different coordinates, average to zero): <|u|^2> = A^2 + B^2 + C^2.
  return 0.5 * rho * L * L * L * (A * A + B * B + C * C) * std::exp(-2.0 * decay_rate() * t);
}

}  // namespace sphmol
