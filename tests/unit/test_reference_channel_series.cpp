// Start-up Couette (Vukčević et al. 2012, eq 23) and Poiseuille (corrected Vukčević et al. 2012, eq 19) series: checked against the
// steady profiles, bounds, boundary conditions, the PDE by finite differences, and each other's
// representations (Fourier vs images) where both converge.
#include <catch2/catch.hpp>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sphmol/reference/couette_series.hpp"
#include "sphmol/reference/poiseuille_series.hpp"
#include "sphmol/reference/repeated_erfc.hpp"

using sphmol::CouetteSeries;
using sphmol::PoiseuilleSeries;

namespace {
// Vukčević et al. 2012, section 4: l = 1e-3 m, nu = 1e-6 m^2/s, F = 2e-4 m/s^2, v0 = 2.5e-5 m/s.
const CouetteSeries couette{1e-3, 1e-6, 2.5e-5};
const PoiseuilleSeries poiseuille{1e-3, 1e-6, 2e-4};
constexpr double accuracy = 1e-14;  // relative to v0 resp. peak velocity

// Times nu t / l^2 spanning tiny to steady; t = tau l^2 / nu.
const double taus[] = {1e-12, 1e-8, 1e-5, 1e-3, 0.005, 0.0199, 0.02, 0.05, 0.1, 0.3, 1.0, 3.0};

template <class S>
double t_of(const S& s, double tau) { return tau * s.l * s.l / s.nu; }

// Residual of u_t - nu u_yy - f at (y, t), relative to the size of the terms, by central differences with
// steps scaled to the local diffusion length.
template <class S>
double pde_residual(const S& s, double y, double t, double f) {
  const double ht = 1e-4 * t;
  const double hy = 1e-3 * std::min(s.l, std::sqrt(s.nu * t));
  const double ut = (s.velocity(y, t + ht) - s.velocity(y, t - ht)) / (2.0 * ht);
  const double uyy = (s.velocity(y + hy, t) - 2.0 * s.velocity(y, t) + s.velocity(y - hy, t)) / (hy * hy);
  const double scale = std::abs(ut) + std::abs(s.nu * uyy) + std::abs(f);
  return std::abs(ut - s.nu * uyy - f) / scale;
}
}  // namespace

TEST_CASE("i2erfc matches its integral form (quadrature) and both branches agree at the switch", "[reference]") {
  // i^2 erfc(x) e^{x^2} = (1/sqrt(pi)) int_0^inf u^2 e^{-2xu - u^2} du  (t = x + u in A&S 7.2.3).
  gsl_integration_workspace* ws = gsl_integration_workspace_alloc(1000);
  for (double x : {0.0, 0.3, 1.0, 1.4999, 1.5, 3.0, 6.0, 12.0, 25.0}) {
    struct P { double x; } p{x};
    gsl_function f;
    f.function = [](double u, void* vp) {
      const double xx = static_cast<P*>(vp)->x;
      return u * u * std::exp(-2.0 * xx * u - u * u);
    };
    f.params = &p;
    double res = 0, err = 0;
    gsl_integration_qagiu(&f, 0.0, 0.0, 1e-13, 1000, ws, &res, &err);
    const double expected = res * std::numbers::inv_sqrtpi;
    INFO("x = " << x);
    CHECK(sphmol::i2erfc(x) * std::exp(x * x) == Approx(expected).epsilon(1e-12));
  }
  gsl_integration_workspace_free(ws);
  CHECK(sphmol::i2erfc(0.0) == Approx(0.25).epsilon(1e-15));
  // Closed form just below the switch vs U form just above: continuous to round-off.
  CHECK(sphmol::i2erfc(std::nextafter(1.5, 0.0)) == Approx(sphmol::i2erfc(1.5)).epsilon(1e-14));
}

TEST_CASE("Couette: Fourier and image series agree to 1e-14 v0 where both converge", "[reference]") {
  double worst = 0.0;
  for (double tau : {0.003, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2}) {
    for (int i = 0; i <= 40; ++i) {
      const double y = couette.l * i / 40.0, t = t_of(couette, tau);
      worst = std::max(worst, std::abs(couette.velocity_fourier(y, t) - couette.velocity_images(y, t)));
    }
  }
  INFO("max |fourier - images| / v0 = " << worst / couette.v0);
  CHECK(worst <= accuracy * couette.v0);
}

TEST_CASE("Poiseuille: Fourier and image series agree to 1e-14 peak where both converge", "[reference]") {
  double worst = 0.0;
  for (double tau : {0.003, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2}) {
    for (int i = 0; i <= 40; ++i) {
      const double y = poiseuille.l * i / 40.0, t = t_of(poiseuille, tau);
      worst = std::max(worst, std::abs(poiseuille.velocity_fourier(y, t) - poiseuille.velocity_images(y, t)));
    }
  }
  INFO("max |fourier - images| / peak = " << worst / poiseuille.peak_velocity());
  CHECK(worst <= accuracy * poiseuille.peak_velocity());
}

TEST_CASE("Couette: steady limit, bounds, boundary values, initial condition", "[reference]") {
  const double v0 = couette.v0, l = couette.l;
  for (int i = 0; i <= 20; ++i) {
    const double y = l * i / 20.0;
    CHECK(std::abs(couette.velocity(y, 100.0) - v0 * y / l) <= accuracy * v0);  // tau = 100: e^{-100 pi^2} = 0
    CHECK(couette.velocity(y, 0.0) == (i == 20 ? v0 : 0.0));
    for (double tau : taus) {
      const double u = couette.velocity(y, t_of(couette, tau));
      CHECK(u >= -accuracy * v0);
      CHECK(u <= v0 * (1.0 + accuracy));
      // Monotone approach: the start-up profile never exceeds the steady one (maximum principle on u - u_s).
      CHECK(u <= v0 * y / l + accuracy * v0);
    }
  }
  for (double tau : taus) {
    const double t = t_of(couette, tau);
    CHECK(std::abs(couette.velocity(0.0, t)) <= accuracy * v0);
    CHECK(std::abs(couette.velocity(l, t) - v0) <= accuracy * v0);
  }
  // Tiny time: momentum has not diffused far; one diffusion length below the plate u = v0 erfc(1/2) (one image).
  const double t = t_of(couette, 1e-6), d = 2.0 * std::sqrt(couette.nu * t);
  CHECK(couette.velocity(l - 0.5 * d, t) == Approx(v0 * std::erfc(0.5)).epsilon(1e-13));
  CHECK(std::abs(couette.velocity(0.5 * l, t)) <= accuracy * v0);
  // Near steady at t = 1 s (Vukčević et al. 2012: "at about t = 1 s the fluid reaches a steady state"): the slowest
  // mode 2 v0/pi e^{-pi^2} sin(pi y/l) remains, about 3e-5 v0 at mid-channel.
  const double mid = couette.velocity(0.5 * l, 1.0);
  CHECK(std::abs(mid - 0.5 * v0) == Approx(2.0 * v0 / std::numbers::pi * std::exp(-std::numbers::pi * std::numbers::pi)).epsilon(1e-6));
}

TEST_CASE("Poiseuille: sign, steady limit, bounds, boundary values, initial condition", "[reference]") {
  const double l = poiseuille.l, F = poiseuille.F, peak = poiseuille.peak_velocity();
  CHECK(peak == Approx(2.5e-5).epsilon(1e-15));  // F l^2/(8 nu) for Vukčević et al. 2012 parameters
  for (int i = 0; i <= 20; ++i) {
    const double y = l * i / 20.0;
    CHECK(std::abs(poiseuille.velocity(y, 100.0) - F / (2.0 * poiseuille.nu) * y * (l - y)) <= accuracy * peak);
    CHECK(poiseuille.velocity(y, 0.0) == 0.0);
    for (double tau : taus) {
      const double t = t_of(poiseuille, tau);
      const double u = poiseuille.velocity(y, t);
      if (i > 0 && i < 20) CHECK(u > 0.0);  // eq 19 as printed would give u < 0 here
      CHECK(u <= F * t + accuracy * peak);
      CHECK(u <= poiseuille.steady_velocity(y) + accuracy * peak);
    }
  }
  for (double tau : taus) {
    const double t = t_of(poiseuille, tau);
    CHECK(std::abs(poiseuille.velocity(0.0, t)) <= accuracy * peak);
    CHECK(std::abs(poiseuille.velocity(l, t)) <= accuracy * peak);
  }
  // Early times: the walls are not felt at mid-channel, u = F t.
  for (double tau : {1e-9, 1e-6, 1e-3}) {
    const double t = t_of(poiseuille, tau);
    CHECK(std::abs(poiseuille.velocity(0.5 * l, t) - F * t) <= accuracy * peak);
  }
  // The midpoint speed rises monotonically towards the peak.
  double prev = 0.0;
  for (double tau : taus) {
    const double u = poiseuille.velocity(0.5 * l, t_of(poiseuille, tau));
    CHECK(u > prev);
    prev = u;
  }
  // Opposite force, opposite flow (the solution is linear in F).
  const PoiseuilleSeries reversed{l, poiseuille.nu, -F};
  CHECK(reversed.velocity(0.3 * l, 0.2) == Approx(-poiseuille.velocity(0.3 * l, 0.2)).epsilon(1e-15));
}

TEST_CASE("Couette and Poiseuille satisfy their PDEs by finite differences", "[reference]") {
  for (double tau : {1e-4, 0.01, 0.0199, 0.021, 0.1, 0.5}) {
    const double tc = t_of(couette, tau), dc = std::sqrt(couette.nu * tc);
    // Couette: points inside the diffusion layer under the moving plate, where u varies.
    for (double y : {couette.l - 0.5 * std::min(dc, 0.5 * couette.l), couette.l - 1.5 * std::min(dc, 0.5 * couette.l)}) {
      INFO("Couette tau = " << tau << " y = " << y);
      CHECK(pde_residual(couette, y, tc, 0.0) < 1e-5);
    }
    const double tp = t_of(poiseuille, tau), dp = std::sqrt(poiseuille.nu * tp);
    for (double y : {0.5 * std::min(dp, 0.3 * poiseuille.l), 1.5 * std::min(dp, 0.3 * poiseuille.l), 0.5 * poiseuille.l}) {
      INFO("Poiseuille tau = " << tau << " y = " << y);
      CHECK(pde_residual(poiseuille, y, tp, poiseuille.F) < 1e-5);
    }
  }
}

TEST_CASE("Channel series reject arguments outside their domain", "[reference]") {
  CHECK_THROWS_AS(couette.velocity(-1e-9, 1.0), std::domain_error);
  CHECK_THROWS_AS(couette.velocity(0.5e-3, -1.0), std::domain_error);
  CHECK_THROWS_AS(poiseuille.velocity(2e-3, 1.0), std::domain_error);
  CHECK_THROWS_AS(poiseuille.velocity_fourier(0.5e-3, 0.0), std::domain_error);
}

TEST_CASE("Channel series match 40-digit values (mpmath, image sums) at Vukčević et al. 2012 parameters", "[reference]") {
  // Values computed independently with mpmath (dps = 40) from the image representations at the double
  // nearest each (y, t); they are reference data, not outputs of this code.
  struct Ref { double y, t, couette, poiseuille; };
  const Ref refs[] = {
      {0.00099, 0.001, 2.0576581843953034594e-5, 6.1958191206246238948e-8},
      {0.00001, 0.001, 0.0, 6.1958191206246214533e-8},
      {0.00025, 0.01, 2.8431814142207372546e-12, 1.9552288503627464576e-6},
      {0.0008, 0.01, 3.9324801762571303638e-6, 1.8864197508592309127e-6},
      {0.0005, 0.3, 1.1676002844189797287e-5, 2.3664186125665814353e-5},
  };
  for (const auto& r : refs) {
    INFO("y = " << r.y << " t = " << r.t);
    CHECK(std::abs(couette.velocity(r.y, r.t) - r.couette) <= accuracy * couette.v0);
    CHECK(std::abs(poiseuille.velocity(r.y, r.t) - r.poiseuille) <= accuracy * poiseuille.peak_velocity());
  }
}
