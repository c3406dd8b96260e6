#pragma once
// Tait equation of state for nearly incompressible water, seed 003 eq 2.75 (Monaghan 1994):
//   p = B ((rho / rho0)^gamma - 1),   B = c0^2 rho0 / gamma,
// so that dp/drho = c0^2 at rho = rho0. c0 is chosen ~10x the largest flow speed (e.g. sqrt(g H)
// for a water column), which keeps density variations near 1 %.
#include <cmath>

#include "sphmol/rhs/term.hpp"

namespace sphmol {

struct TaitLaw {
  double rho0 = 1.0, gamma = 7.0, B = 0.0;
  TaitLaw(double sound_speed, double rest_density, double exponent)
      : rho0(rest_density), gamma(exponent), B(sound_speed * sound_speed * rest_density / exponent) {}
  double pressure(double rho) const { return B * (std::pow(rho / rho0, gamma) - 1.0); }
  double density(double p) const { return rho0 * std::pow(p / B + 1.0, 1.0 / gamma); }  // inverse
};

template <int D>
class TaitEos final : public Term<D> {
 public:
  TaitEos(double sound_speed, double rest_density, double gamma) : law_(sound_speed, rest_density, gamma) {}
  std::string_view name() const override { return "eos_tait"; }
  void apply(Workspace<D>& w) const override {
    for (std::size_t i = 0; i < w.n; ++i) w.p[i] = law_.pressure(w.rho[i]);
  }
  const TaitLaw& law() const { return law_; }

 private:
  TaitLaw law_;
};

}  // namespace sphmol
