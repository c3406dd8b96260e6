// Taylor-Green vortex: divergence-free and satisfies incompressible Navier-Stokes by finite differences.
#include <catch2/catch.hpp>
#include <numbers>

#include <algorithm>
#include <cmath>

#include "sphmol/reference/taylor_green.hpp"

using sphmol::TaylorGreenVortex;

TEST_CASE("Taylor-Green: divergence-free and momentum equation by finite differences", "[reference][taylor_green]") {
  const TaylorGreenVortex tg{1.5, 100.0, 2.0};
  const double h = 1e-4, ht = 1e-5;
  for (double t : {0.0, 0.1, 1.0}) {
    double worst_div = 0.0, worst_mx = 0.0, worst_my = 0.0;
    for (double x : {0.03, 0.17, 0.4, 0.61, 0.88}) {
      for (double y : {0.07, 0.29, 0.5, 0.73, 0.94}) {
        auto d = [&](auto f, int dir) {  // central first derivative in x (0), y (1), t (2)
          if (dir == 0) return (f(x + h, y, t) - f(x - h, y, t)) / (2 * h);
          if (dir == 1) return (f(x, y + h, t) - f(x, y - h, t)) / (2 * h);
          return (f(x, y, t + ht) - f(x, y, t - ht)) / (2 * ht);
        };
        auto lap = [&](auto f) {
          return (f(x + h, y, t) + f(x - h, y, t) + f(x, y + h, t) + f(x, y - h, t) - 4 * f(x, y, t)) / (h * h);
        };
        auto U = [&](double a, double b, double c) { return tg.u(a, b, c); };
        auto V = [&](double a, double b, double c) { return tg.v(a, b, c); };
        auto P = [&](double a, double b, double c) { return tg.pressure(a, b, c); };
        const double u = tg.u(x, y, t), v = tg.v(x, y, t);
        const double scale = tg.U * tg.U * std::exp(2 * tg.decay_rate() * t) * 2 * std::numbers::pi + tg.U * std::exp(tg.decay_rate() * t);
        worst_div = std::max(worst_div, std::abs(d(U, 0) + d(V, 1)) / scale);
        const double rx = d(U, 2) + u * d(U, 0) + v * d(U, 1) + d(P, 0) / tg.rho - tg.nu() * lap(U);
        const double ry = d(V, 2) + u * d(V, 0) + v * d(V, 1) + d(P, 1) / tg.rho - tg.nu() * lap(V);
        worst_mx = std::max(worst_mx, std::abs(rx) / scale);
        worst_my = std::max(worst_my, std::abs(ry) / scale);
      }
    }
    INFO("t = " << t << " div " << worst_div << " mom " << worst_mx << ", " << worst_my);
    CHECK(worst_div < 1e-8);
    CHECK(worst_mx < 1e-6);
    CHECK(worst_my < 1e-6);
  }
}

TEST_CASE("Taylor-Green: pressure sign, periodicity, decay, kinetic energy", "[reference][taylor_green]") {
  const TaylorGreenVortex tg{1.0, 50.0, 1.0};
  CHECK(tg.decay_rate() == Approx(-8.0 * std::numbers::pi * std::numbers::pi / 50.0));  // b = -8 pi^2 / Re for U = L = 1
  // Vortex centre (0.25, 0.25): stagnant and a pressure minimum; the saddle (0, 0) is a maximum.
  CHECK(std::abs(tg.u(0.25, 0.25, 0.0)) < 1e-15);
  CHECK(tg.pressure(0.25, 0.25, 0.0) == Approx(0.5));
  CHECK(tg.pressure(0.0, 0.0, 0.0) == Approx(-0.5));
  // Periodic on the unit square.
  CHECK(tg.u(0.3 + 1.0, 0.7, 0.2) == Approx(tg.u(0.3, 0.7, 0.2)).epsilon(1e-12));
  CHECK(tg.v(0.3, 0.7 + 1.0, 0.2) == Approx(tg.v(0.3, 0.7, 0.2)).epsilon(1e-12));
  // Amplitude decays as e^{bt}.
  CHECK(tg.u(0.1, 0.2, 0.5) / tg.u(0.1, 0.2, 0.0) == Approx(std::exp(tg.decay_rate() * 0.5)).epsilon(1e-14));
  // Kinetic energy by midpoint quadrature on a 64^2 grid (exact for these trigonometric polynomials).
  const int n = 64;
  double ke = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = (i + 0.5) / n, y = (j + 0.5) / n, u = tg.u(x, y, 0.3), v = tg.v(x, y, 0.3);
      ke += 0.5 * tg.rho * (u * u + v * v) / (n * n);
    }
  CHECK(ke == Approx(tg.kinetic_energy(0.3)).epsilon(1e-13));
}
