#pragma once
// Tait equation of state for nearly incompressible water, Niedoba 2012, eq 2.75 (Monaghan 1994):
//   p = B ((rho / rho0)^gamma - 1),   B = c0^2 rho0 / gamma,
// so that dp/drho = c0^2 at rho = rho0. c0 is chosen ~10x the largest flow speed (e.g. sqrt(g H)
// for a water column), which keeps density variations near 1 %. Fluids of several rest densities
// (a scene's fluid bodies with their own `density`, Particles::rest_density) take the multiphase form
// of Colagrossi & Landrini (2003, J. Comput. Phys. 191:448): each particle its own rho0_i and
// B_i = c0^2 rho0_i / gamma, with one c0, so that every phase is at p = 0 at its own rest density.
#include <algorithm>
#include <cmath>
#include <vector>

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
      : law_(sound_speed, rest_density, gamma),
        floor_(clamp_negative ? 0.0 : -HUGE_VAL),
        whole_gamma_(gamma >= 1.0 && gamma <= 64.0 && gamma == std::floor(gamma) ? static_cast<unsigned>(gamma) : 0u) {}
  std::string_view name() const override { return floor_ == 0.0 ? "eos_tait_clamped" : "eos_tait"; }
  // Also the local sound speed c_i = sqrt(dp/drho) = c0 (rho/rho0)^((gamma-1)/2), which the artificial
  // viscosity and the CFL limit read (without it they would see c = 0).
  void apply(Workspace<D>& w) const override {
    // A whole exponent (gamma = 7 for water) by repeated squaring: four multiplications instead of a
    // pow call, which was 4 % of a dam-break step (perf); within a few ulp of pow.
    if (whole_gamma_ > 0)
      run(w, [n = whole_gamma_](const double* r, double* rg, std::size_t m) { power_run(r, rg, m, n); });
    else
      run(w, [g = law_.gamma](const double* r, double* rg, std::size_t m) {
        for (std::size_t k = 0; k < m; ++k) rg[k] = std::pow(r[k], g);
      });
  }
  bool runs_in_team() const override { return true; }  // worksharing loops only (Term::runs_in_team)
  const TaitLaw& law() const { return law_; }
  // x^n for n >= 1, by squaring.
  static double power(double x, unsigned n) {
    double result = (n & 1u) ? x : 1.0;
    for (n >>= 1u; n > 0; n >>= 1u) {
      x *= x;
      if (n & 1u) result *= x;
    }
    return result;
  }
  // power(x[k], n) for k in [0, m <= kRun): the same multiplications in the same order, one sweep over
  // the run per bit of n, so that they vectorise.
  static constexpr std::size_t kRun = 64;
  static void power_run(const double* x, double* result, std::size_t m, unsigned n) {
    double sq[kRun];
    for (std::size_t k = 0; k < m; ++k) {
      sq[k] = x[k];
      result[k] = (n & 1u) ? x[k] : 1.0;
    }
    for (n >>= 1u; n > 0; n >>= 1u) {
      for (std::size_t k = 0; k < m; ++k) sq[k] *= sq[k];
      if (n & 1u)
        for (std::size_t k = 0; k < m; ++k) result[k] *= sq[k];
    }
  }

 private:
  // The particles in runs of kRun: rho / rho0_i, its power, then p and c, each a loop that vectorises.
  template <class PowRun>
  void run(Workspace<D>& w, PowRun pow_run) const {
    const double c0 = std::sqrt(law_.B * law_.gamma / law_.rho0);
    // The particles' own rest densities (Particles::rest_density), for [0, size); the rest (generated
    // particles) keep rho0. A workspace without particles (unit tests of the law alone) has no rest densities of its own.
    const double* own = w.particles ? w.particles->rest_density.data() : nullptr;
    const std::size_t n_own = w.particles ? std::min(w.particles->rest_density.size(), w.n) : 0;
    // B_i / rho0_i = B / rho0 for every phase (one c0).
    const double b_per_rho0 = law_.B / law_.rho0, floor = floor_, rho0 = law_.rho0, B = law_.B;
    const double* const rho = w.rho.data();
    double* const p = w.p.data();
    double* const c = w.c.data();
    const std::size_t runs_own = (n_own + kRun - 1) / kRun;
#pragma omp for schedule(static) nowait
    for (std::size_t b = 0; b < runs_own; ++b) {
      const std::size_t i0 = b * kRun, m = std::min(kRun, n_own - i0);
      double r[kRun], rg[kRun];
      for (std::size_t k = 0; k < m; ++k) r[k] = rho[i0 + k] / own[i0 + k];
      pow_run(r, rg, m);
      for (std::size_t k = 0; k < m; ++k) {
        p[i0 + k] = std::max(floor, b_per_rho0 * own[i0 + k] * (rg[k] - 1.0));
        c[i0 + k] = c0 * std::sqrt(rg[k] / r[k]);
      }
    }
    const std::size_t rest = w.n - n_own, runs_rest = (rest + kRun - 1) / kRun;
#pragma omp for schedule(static)
    for (std::size_t b = 0; b < runs_rest; ++b) {
      const std::size_t i0 = n_own + b * kRun, m = std::min(kRun, w.n - i0);
      double r[kRun], rg[kRun];
      for (std::size_t k = 0; k < m; ++k) r[k] = rho[i0 + k] / rho0;
      pow_run(r, rg, m);
      for (std::size_t k = 0; k < m; ++k) {
        p[i0 + k] = std::max(floor, B * (rg[k] - 1.0));
        c[i0 + k] = c0 * std::sqrt(rg[k] / r[k]);
      }
    }
  }

  TaitLaw law_;
  double floor_;
  unsigned whole_gamma_;  // gamma when it is a whole number in [1, 64], else 0 (std::pow)
};

}  // namespace sphmol
