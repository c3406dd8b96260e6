#pragma once
// Tait equation of state for nearly incompressible water, seed 003 eq 2.75 (Monaghan 1994):
//   p = B ((rho / rho0)^gamma - 1),   B = c0^2 rho0 / gamma,
// so that dp/drho = c0^2 at rho = rho0. c0 is chosen ~10x the largest flow speed (e.g. sqrt(g H)
// for a water column), which keeps density variations near 1 %.
#include <algorithm>
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
  // clamp_negative: p = max(p, 0). Summation density is deficient at a free surface (about rho0/2 on
  // the top row), where Tait then gives p ~ -B, far larger than rho0 g H: the surface rows would be
  // pulled into the column. Clamping is the usual remedy with summation density (fluid.eos.clamp_negative).
  TaitEos(double sound_speed, double rest_density, double gamma, bool clamp_negative = false)
      : law_(sound_speed, rest_density, gamma), floor_(clamp_negative ? 0.0 : -HUGE_VAL) {}
  std::string_view name() const override { return floor_ == 0.0 ? "eos_tait_clamped" : "eos_tait"; }
  void apply(Workspace<D>& w) const override {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < w.n; ++i) w.p[i] = std::max(floor_, law_.pressure(w.rho[i]));
  }
  const TaitLaw& law() const { return law_; }

 private:
  TaitLaw law_;
  double floor_;
};

}  // namespace sphmol
