// The start-up of a linear flow under a body force ramped in with body_force_ramp_factor
// (reference/ramped_start.hpp), checked on the Poiseuille channel against a closed form derived
// independently, mode by mode: with the step response u_step = S(y) - sum_n a_n(y) e^{-k_n t},
// k_n = (2n+1)^2 pi^2 nu / l^2, and r'(tau) = (w/2) sin(w tau), w = pi / ramp, m = min(t, ramp):
//   u(t) = r(m) S(y) - sum_n a_n(y) (w/2) [e^{-k_n (t - m)} (k_n sin(w m) - w cos(w m)) + w e^{-k_n t}] / (k_n^2 + w^2).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sphmol/physics/body_force.hpp"
#include "sphmol/reference/poiseuille_series.hpp"
#include "sphmol/reference/ramped_start.hpp"

using sphmol::PoiseuilleSeries;
using sphmol::ramped_start;

namespace {

const PoiseuilleSeries channel{1e-3, 1e-6, 2e-4};  // Vukčević et al. 2012, section 4

// The closed form above; its terms fall off as n^-5 while the ramp runs (n^-3 e^{-k_n (t - ramp)} after).
double ramped_modes(const PoiseuilleSeries& p, double y, double t, double ramp) {
  const double pi = std::numbers::pi, w = pi / ramp, m = std::min(t, ramp);
  const double peak = p.peak_velocity();
  double u = sphmol::body_force_ramp_factor(m, ramp) * p.steady_velocity(y);
  for (int j = 0; j < 200000; ++j) {
    const double n = 2.0 * j + 1.0;
    const double k = n * n * pi * pi * p.nu / (p.l * p.l);
    const double a = peak * 32.0 / (pi * pi * pi * n * n * n) * std::sin(n * pi * y / p.l);
    u -= a * 0.5 * w * (std::exp(-k * (t - m)) * (k * std::sin(w * m) - w * std::cos(w * m)) + w * std::exp(-k * t)) / (k * k + w * w);
  }
  return u;
}

double u_step(const PoiseuilleSeries& p, double y, double t) { return p.velocity(y, t); }

}  // namespace

TEST_CASE("ramped_start: the Poiseuille start-up under a ramped force matches its mode-by-mode closed form", "[reference]") {
  const double peak = channel.peak_velocity();
  // l^2 / nu = 1 s: ramps short and long against the viscous time, times during and after the ramp.
  for (double ramp : {0.01, 0.1, 0.5}) {
    for (double t : {0.002, 0.005, 0.05, 0.1, 0.3, 0.6, 2.0}) {
      for (double y : {0.0, 0.05e-3, 0.25e-3, 0.5e-3, 0.9e-3}) {
        const double u = ramped_start([&](double s) { return u_step(channel, y, s); }, t, ramp, 1e-14 * peak);
        INFO("ramp " << ramp << " t " << t << " y " << y << ": " << u << " vs " << ramped_modes(channel, y, t, ramp));
        CHECK(std::abs(u - ramped_modes(channel, y, t, ramp)) < 1e-11 * peak);
      }
    }
  }
}

TEST_CASE("ramped_start: no ramp is the step response, rest at t = 0, and the ramped flow lags the step response", "[reference]") {
  const double peak = channel.peak_velocity(), y = 0.5e-3;
  auto step = [&](double s) { return u_step(channel, y, s); };
  CHECK(ramped_start(step, 0.3, 0.0, 1e-14 * peak) == channel.velocity(y, 0.3));
  CHECK(ramped_start(step, 0.0, 0.1, 1e-14 * peak) == 0.0);
  for (double t : {0.01, 0.05, 0.1, 0.2}) {
    const double u = ramped_start(step, t, 0.1, 1e-14 * peak);
    CHECK(u > 0.0);
    CHECK(u < channel.velocity(y, t));
  }
  // Long after the ramp the flow is the steady profile.
  CHECK(std::abs(ramped_start(step, 20.0, 0.1, 1e-14 * peak) - channel.steady_velocity(y)) < 1e-12 * peak);
  // While the walls' diffusion length 2 sqrt(nu t) is far below the half width (t = 2 ms: 8.9e-5 m
  // against 5e-4 m), mid-channel fluid just accelerates: u = int_0^t F r = F / 2 (t - ramp sin(pi t / ramp) / pi).
  const double ramp = 0.5, t = 0.002;
  const double plug = channel.F * ramp / 2.0 * (t / ramp - std::sin(std::numbers::pi * t / ramp) / std::numbers::pi);
  CHECK(std::abs(ramped_start(step, t, ramp, 1e-14 * peak) - plug) < 1e-6 * plug);
  CHECK_THROWS(ramped_start(step, -1.0, 0.1, 1e-14 * peak));
}
