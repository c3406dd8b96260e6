// The three-dimensional references: the rectangular-duct series (steady White 2006, eqs 3-48 and 3-49;
// start-up double series and its Duhamel form) and the decaying ABC flow. Checked against published
// constants, the plane-channel limit, symmetry, the boundary conditions, each other's representations,
// and the governing equations by finite differences.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <numbers>

#include "sphmol/reference/abc_flow.hpp"
#include "sphmol/reference/duct_series.hpp"
#include "sphmol/reference/poiseuille_series.hpp"

using sphmol::AbcFlow;
using sphmol::DuctSeries;

namespace {
// Unit square of half-side a = 1 with g = nu = 1: velocities are in units of g a^2 / nu.
const DuctSeries square{1.0, 1.0, 1.0, 1.0};
}  // namespace

TEST_CASE("Duct: the square duct's centre and mean velocities match the published constants", "[reference][duct]") {
  // Shah & London 1978, ch. VII (rectangular ducts), aspect ratio 1: f Re = 14.22708 with the hydraulic
  // diameter D_h = 2a, and u_max / u_m = 2.0962. With f Re = D_h^2 g/(2 nu u_m) (Fanning factor):
  // u_m = 4 a^2 g/(2 nu f Re) = 0.140577 g a^2/nu.
  const double f_re = 14.22708;
  const double mean = 4.0 / (2.0 * f_re);
  CHECK(square.mean_velocity() == Approx(mean).epsilon(2e-6));
  CHECK(square.centre_velocity() / square.mean_velocity() == Approx(2.0962).epsilon(3e-5));
  // Independent of the tables: the centre speed from the double series at large t (a separate
  // representation of the same solution) and the literature's 0.29468.
  CHECK(square.centre_velocity() == Approx(0.29468).epsilon(2e-5));
  CHECK(square.velocity_fourier(0.0, 0.0, 50.0) == Approx(square.centre_velocity()).epsilon(1e-13));
}

TEST_CASE("Duct: the mean velocity is the area average of the steady profile", "[reference][duct]") {
  // Gauss-Legendre would do better, but the midpoint rule on a fine grid of a smooth profile vanishing
  // on the walls is second order and enough for 1e-5.
  for (const DuctSeries d : {DuctSeries{1.0, 1.0, 1.0, 1.0}, DuctSeries{0.5, 1.5, 2.0, 3.0}}) {
    const int n = 200;
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        sum += d.steady_velocity(-d.a + (i + 0.5) * 2.0 * d.a / n, -d.b + (j + 0.5) * 2.0 * d.b / n);
    CHECK(sum / (n * n) == Approx(d.mean_velocity()).epsilon(1e-4));
  }
}

TEST_CASE("Duct: a wide duct is the plane channel away from its side walls", "[reference][duct]") {
  const DuctSeries wide{1.0, 30.0, 1.0, 1.0};
  for (double y : {0.0, 0.3, -0.7, 0.99}) {
    INFO("y = " << y);
    CHECK(wide.steady_velocity(y, 0.0) == Approx(0.5 * (1.0 - y * y)).margin(1e-14));
    CHECK(wide.steady_velocity(y, 10.0) == Approx(0.5 * (1.0 - y * y)).margin(1e-12));
  }
  // Plane-channel mean g a^2/(3 nu) corrected by the side walls, 1 - 192 a (1 - 2^-5) zeta(5)/(pi^5 b)
  // (the tanh factors are 1 to e^{-30 pi}).
  CHECK(wide.mean_velocity() == Approx(1.0 / 3.0 * (1.0 - 192.0 / std::pow(std::numbers::pi, 5) / 30.0 * 1.0045237627951087)).epsilon(1e-12));
}

TEST_CASE("Duct: the profile is symmetric, zero on the walls, and exchanging (y, a) with (z, b) changes nothing", "[reference][duct]") {
  const DuctSeries d{0.6, 1.1, 0.7, 2.0};
  const DuctSeries swapped{1.1, 0.6, 0.7, 2.0};
  for (double y : {0.0, 0.2, 0.45, 0.59}) {
    for (double z : {0.0, 0.5, 1.0, 1.09}) {
      INFO("y = " << y << ", z = " << z);
      const double u = d.steady_velocity(y, z);
      CHECK(u > 0.0);
      CHECK(d.steady_velocity(-y, z) == Approx(u).epsilon(1e-13));
      CHECK(d.steady_velocity(y, -z) == Approx(u).epsilon(1e-13));
      CHECK(swapped.steady_velocity(z, y) == Approx(u).epsilon(1e-12));
      for (double t : {0.05, 0.3, 2.0}) CHECK(d.velocity(-y, -z, t) == Approx(d.velocity(y, z, t)).epsilon(1e-12));
    }
  }
  for (double s : {-1.0, -0.3, 0.0, 0.8, 1.0}) {
    CHECK(d.steady_velocity(0.6, 1.1 * s) == 0.0);
    CHECK(d.steady_velocity(0.6 * s, -1.1) == 0.0);
    // Close to the wall the profile is linear in the distance: u / distance stays bounded.
    CHECK(std::abs(d.steady_velocity(0.6 * 0.9 * s, 1.1 - 1e-9)) < 1e-9 * 2.0 * 1.1 * 2.0 / 0.7);
  }
  CHECK(d.velocity(0.6, 0.0, 0.5) == 0.0);
}

TEST_CASE("Duct: the steady profile satisfies nu lap u = -g (finite differences)", "[reference][duct]") {
  const DuctSeries d{0.6, 1.1, 0.7, 2.0};
  const double h = 2e-4;  // small: the profile curves sharply 0.05 from a corner
  for (double y : {0.0, 0.3, 0.55}) {
    for (double z : {0.0, 0.7, 1.05}) {
      const double lap = (d.steady_velocity(y + h, z) + d.steady_velocity(y - h, z) + d.steady_velocity(y, z + h) +
                          d.steady_velocity(y, z - h) - 4.0 * d.steady_velocity(y, z)) / (h * h);
      INFO("y = " << y << ", z = " << z);
      CHECK(d.nu * lap == Approx(-d.g).epsilon(1e-5));
    }
  }
}

TEST_CASE("Duct: the start-up satisfies u_t = nu lap u + g and the two representations agree", "[reference][duct]") {
  const DuctSeries d{0.6, 1.1, 0.7, 2.0};
  const double c2_over_nu = 0.36 / 0.7;
  for (double tau : {0.005, 0.0199, 0.02, 0.1, 0.5}) {
    const double t = tau * c2_over_nu;
    for (double y : {0.0, 0.5}) {
      for (double z : {0.0, 1.0}) {
        INFO("tau = " << tau << ", y = " << y << ", z = " << z);
        const double ht = 1e-4 * t;
        const double h = 1e-3 * std::min(0.6, std::sqrt(d.nu * t));
        const double ut = (d.velocity(y, z, t + ht) - d.velocity(y, z, t - ht)) / (2.0 * ht);
        const double lap = (d.velocity(y + h, z, t) + d.velocity(y - h, z, t) + d.velocity(y, z + h, t) +
                            d.velocity(y, z - h, t) - 4.0 * d.velocity(y, z, t)) / (h * h);
        CHECK(std::abs(ut - d.nu * lap - d.g) < 2e-4 * (std::abs(ut) + std::abs(d.nu * lap) + d.g));
        if (tau >= 0.005) CHECK(d.velocity_fourier(y, z, t) == Approx(d.velocity_duhamel(y, z, t)).margin(1e-12));
      }
    }
  }
}

TEST_CASE("Duct: the start-up grows monotonically from rest to the steady profile", "[reference][duct]") {
  CHECK(square.velocity(0.3, 0.2, 0.0) == 0.0);
  // At tiny times the core moves as if unbounded, u = g t.
  CHECK(square.velocity(0.0, 0.0, 1e-4) == Approx(1e-4).epsilon(1e-12));
  double previous = 0.0;
  for (double t : {0.001, 0.01, 0.05, 0.2, 0.5, 1.0, 2.0, 4.0}) {
    const double u = square.velocity(0.0, 0.0, t);
    CHECK(u > previous);
    previous = u;
  }
  // The slowest mode decays as e^{-nu lambda_11 t}, lambda_11 = pi^2/2 for the unit half-side square.
  const double t = 4.0;
  const double defect = square.centre_velocity() - square.velocity(0.0, 0.0, t);
  const double lambda = std::numbers::pi * std::numbers::pi / 2.0;
  const double leading = 16.0 / (std::numbers::pi * std::numbers::pi * lambda) * std::exp(-lambda * t);
  CHECK(defect == Approx(leading).epsilon(1e-6));
  CHECK(square.velocity(0.4, -0.7, 20.0) == Approx(square.steady_velocity(0.4, -0.7)).epsilon(1e-14));
}

TEST_CASE("Duct: a wide duct's start-up at the centre is the plane Poiseuille start-up", "[reference][duct]") {
  const DuctSeries wide{0.5, 10.0, 1e-2, 0.3};
  const sphmol::PoiseuilleSeries channel{1.0, 1e-2, 0.3};  // plates at y = 0 and 1: y_channel = y + a
  for (double t : {0.01, 0.5, 2.0, 5.0, 20.0, 100.0}) {
    INFO("t = " << t);
    CHECK(wide.velocity(0.0, 0.0, t) == Approx(channel.velocity(0.5, t)).margin(1e-13 * channel.peak_velocity()));
    CHECK(wide.velocity(0.3, 2.0, t) == Approx(channel.velocity(0.8, t)).margin(1e-13 * channel.peak_velocity()));
  }
}

TEST_CASE("Duct: invalid parameters and points are rejected", "[reference][duct]") {
  CHECK_THROWS_AS((DuctSeries{0.0, 1.0, 1.0, 1.0}.steady_velocity(0.0, 0.0)), std::domain_error);
  CHECK_THROWS_AS((DuctSeries{1.0, 1.0, -1.0, 1.0}.mean_velocity()), std::domain_error);
  CHECK_THROWS_AS(square.steady_velocity(1.1, 0.0), std::domain_error);
  CHECK_THROWS_AS(square.velocity(0.0, 0.0, -1.0), std::domain_error);
  CHECK_THROWS_AS(square.velocity(0.0, 0.0, NAN), std::domain_error);
}

namespace {
const AbcFlow abc{1.0, 0.7, 0.4, 2.0, 0.05, 1.3, 10.0};

std::array<double, 3> u_at(double x, double y, double z, double t) { return abc.velocity(x, y, z, t); }
}  // namespace

TEST_CASE("ABC flow: divergence free and Beltrami, curl u = k u (finite differences)", "[reference][abc]") {
  const double h = 1e-4;
  const double k = abc.wavenumber();
  CHECK(k == Approx(std::numbers::pi));
  for (const auto& p : {std::array<double, 3>{0.1, 0.2, 0.3}, {1.3, 0.4, 1.9}, {0.77, 1.51, 0.05}}) {
    const double t = 0.7;
    auto d = [&](int comp, int dir) {
      std::array<double, 3> a = p, b = p;
      a[dir] += h;
      b[dir] -= h;
      return (u_at(a[0], a[1], a[2], t)[comp] - u_at(b[0], b[1], b[2], t)[comp]) / (2.0 * h);
    };
    const auto u = u_at(p[0], p[1], p[2], t);
    CHECK(std::abs(d(0, 0) + d(1, 1) + d(2, 2)) < 1e-8);
    CHECK(d(2, 1) - d(1, 2) == Approx(k * u[0]).margin(1e-7));
    CHECK(d(0, 2) - d(2, 0) == Approx(k * u[1]).margin(1e-7));
    CHECK(d(1, 0) - d(0, 1) == Approx(k * u[2]).margin(1e-7));
  }
}

TEST_CASE("ABC flow: the Navier-Stokes momentum residual vanishes (finite differences)", "[reference][abc]") {
  const double h = 1e-3;
  const double ht = 1e-4;
  for (const auto& p : {std::array<double, 3>{0.1, 0.2, 0.3}, {1.3, 0.4, 1.9}, {0.77, 1.51, 0.05}}) {
    for (double t : {0.0 + ht, 0.5, 3.0}) {
      const auto u = u_at(p[0], p[1], p[2], t);
      auto shifted = [&](int dir, double s) {
        std::array<double, 3> q = p;
        q[dir] += s;
        return q;
      };
      for (int c = 0; c < 3; ++c) {
        const double ut = (u_at(p[0], p[1], p[2], t + ht)[c] - u_at(p[0], p[1], p[2], t - ht)[c]) / (2.0 * ht);
        double adv = 0.0, lap = 0.0;
        for (int dir = 0; dir < 3; ++dir) {
          const auto a = shifted(dir, h), b = shifted(dir, -h);
          const double ua = u_at(a[0], a[1], a[2], t)[c], ub = u_at(b[0], b[1], b[2], t)[c];
          adv += u[dir] * (ua - ub) / (2.0 * h);
          lap += (ua - 2.0 * u[c] + ub) / (h * h);
        }
        const auto a = shifted(c, h), b = shifted(c, -h);
        const double dp = (abc.pressure(a[0], a[1], a[2], t) - abc.pressure(b[0], b[1], b[2], t)) / (2.0 * h);
        const double residual = ut + adv + dp / abc.rho - abc.nu * lap;
        INFO("t = " << t << ", component " << c);
        CHECK(std::abs(residual) < 1e-5 * (std::abs(ut) + std::abs(adv) + std::abs(dp / abc.rho) + 1e-3));
      }
    }
  }
}

TEST_CASE("ABC flow: pressure, kinetic energy and decay", "[reference][abc]") {
  CHECK(abc.decay_rate() == Approx(0.05 * std::numbers::pi * std::numbers::pi));
  // Where u = 0 the pressure is p0; elsewhere below it.
  CHECK(abc.pressure(0.3, 0.9, 1.2, 0.4) < abc.p0);
  // Kinetic energy by the midpoint rule (exact for trigonometric polynomials of low degree on a periodic grid).
  const int n = 16;
  const double cell = abc.L / n;
  for (double t : {0.0, 1.0, 4.0}) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int l = 0; l < n; ++l) {
          const auto u = abc.velocity((i + 0.5) * cell, (j + 0.5) * cell, (l + 0.5) * cell, t);
          sum += 0.5 * abc.rho * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * cell * cell * cell;
        }
    CHECK(sum == Approx(abc.kinetic_energy(t)).epsilon(1e-12));
  }
  const auto u0 = abc.velocity(0.3, 0.9, 1.2, 0.0);
  const auto u1 = abc.velocity(0.3, 0.9, 1.2, 2.0);
  for (int c = 0; c < 3; ++c) CHECK(u1[c] == Approx(u0[c] * std::exp(-abc.decay_rate() * 2.0)).epsilon(1e-14));
}
