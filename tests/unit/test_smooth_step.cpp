// The C-infinity step (core/smooth_step.hpp), and the artificial viscosity's smooth approaching-pair
// switch (physics/artificial_viscosity.hpp), built on the C^6 polynomial step of core/polynomial_step.hpp.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "sphmol/core/smooth_step.hpp"
#include "sphmol/physics/artificial_viscosity.hpp"

using namespace sphmol;

TEST_CASE("smooth step: 0 below 0, 1 above 1, monotone, symmetric, derivative consistent", "[smooth_step]") {
  for (double t : {-1e300, -2.0, -1e-300, -0.0, 0.0}) CHECK(smooth_step(t) == 0.0);
  for (double t : {1.0, 1.0 + 1e-15, 3.0, 1e300}) CHECK(smooth_step(t) == 1.0);
  CHECK(smooth_step(std::numeric_limits<double>::quiet_NaN()) == 0.0);
  CHECK(smooth_step(0.5) == Approx(0.5).epsilon(1e-15));
  double prev = 0.0;
  for (int k = 1; k < 1000; ++k) {
    const double t = k / 1000.0, s = smooth_step(t);
    CHECK(s >= prev);
    prev = s;
    CHECK(s + smooth_step(1.0 - t) == Approx(1.0).epsilon(1e-14));
    double s2, ds;
    smooth_step(t, s2, ds);
    CHECK(s2 == Approx(s).epsilon(1e-14).margin(1e-300));
    const double e = 1e-6;
    CHECK(ds == Approx((smooth_step(t + e) - smooth_step(t - e)) / (2 * e)).epsilon(1e-6).margin(1e-9));
    CHECK(ds >= 0.0);
  }
  double s, ds;
  smooth_step(0.0, s, ds);
  CHECK((s == 0.0 && ds == 0.0));
  smooth_step(1.0, s, ds);
  CHECK((s == 1.0 && ds == 0.0));
  smooth_step(1e-3, s, ds);  // exp(-1000) underflows: no NaN from 0 * inf
  CHECK((s == 0.0 && ds == 0.0));
}

TEST_CASE("smooth step is flat to every order at its ends (C-infinity, not C^m)", "[smooth_step]") {
  // A step that is C^m at t = 0 behaves like t^(m+1) there: S(t) / S(2t) -> 2^-(m+1). Here the ratio
  // falls below any power: exp(-1/t + 1/(2t)) up to the denominators. (The end t = 1 is the same by
  // S(t) + S(1 - t) = 1, checked above.)
  for (double t : {0.025, 0.01}) {
    CHECK(smooth_step(t) / smooth_step(2 * t) < std::pow(2.0, -20));
  }
}

TEST_CASE("smooth min(x, 0), the switch at offset 0: exact outside the band, of the right sign inside, width 0 is the kink",
          "[smooth_step]") {
  // switched_vx(x, width, 0) = x S(-x / width).
  const double w = 0.3;
  for (double x : {-5.0, -0.3, -0.3 - 1e-12}) CHECK(switched_vx(x, w, 0.0) == x);
  for (double x : {0.0, 1e-300, 0.1, 7.0}) CHECK(switched_vx(x, w, 0.0) == 0.0);
  for (double x : {-0.29, -0.15, -0.01}) {
    CHECK(switched_vx(x, w, 0.0) < 0.0);
    CHECK(switched_vx(x, w, 0.0) > x);
  }
  for (double x : {-2.0, -1e-300, 0.0, 1e-300, 3.0}) CHECK(switched_vx(x, 0.0, 0.0) == std::min(x, 0.0));
}

TEMPLATE_TEST_CASE("the sharp switch's shortcut is the width-0 switch bit for bit, signed zeros and NaN included",
                   "[smooth_step][physics]", MonaghanPi, SignalVelocityPi) {
  // ArtificialViscosity takes Pi::sharp (no polynomial) for its rows at width 0.
  TestType pi{};
  pi.alpha = 1.0;
  pi.beta = 2.0;
  if constexpr (std::is_same_v<TestType, MonaghanPi>) pi.eta = 0.1;
  const auto bits = [](double x) {
    std::uint64_t u;
    std::memcpy(&u, &x, sizeof u);
    return u;
  };
  for (const double vx : {-3.0, -1e-300, -0.0, 0.0, 1e-300, 2.0, std::numeric_limits<double>::quiet_NaN()})
    for (const double r2 : {0.0, 1e-4, 2.5}) {
      CAPTURE(vx, r2);
      CHECK(bits(pi.sharp(vx, r2, 0.013, 1.7, 998.0)) == bits(pi(vx, r2, 0.013, 1.7, 998.0)));
    }
}

TEMPLATE_TEST_CASE("smooth viscosity switch: Monaghan outside the band, zero when receding, Pi >= 0, smooth at 0",
                   "[smooth_step][physics]", MonaghanPi, SignalVelocityPi) {
  const double r2 = 0.04, hij = 0.13, cbar = 3.0, rhobar = 1.2, width = 0.01;
  TestType sharp, smooth;
  if constexpr (std::is_same_v<TestType, MonaghanPi>) {
    sharp = MonaghanPi{1.0, 2.0, 0.1};
    smooth = MonaghanPi{1.0, 2.0, 0.1, width};
  } else {
    sharp = SignalVelocityPi{1.0, 2.0};
    smooth = SignalVelocityPi{1.0, 2.0, width};
  }
  const double delta = width * cbar * hij;  // the band in v_ij . x_ij
  // Approaching faster than the band: Monaghan's Pi exactly.
  for (double vx : {-1.0, -0.1, -delta, -delta * (1 + 1e-12)}) CHECK(smooth(vx, r2, hij, cbar, rhobar) == sharp(vx, r2, hij, cbar, rhobar));
  // Receding (and at rest): nothing, as before.
  for (double vx : {0.0, 1e-300, 1e-3, 1.0}) {
    CHECK(smooth(vx, r2, hij, cbar, rhobar) == 0.0);
    CHECK(sharp(vx, r2, hij, cbar, rhobar) == 0.0);
  }
  // In the band: dissipative (Pi >= 0, as the heating 1/2 m Pi F v_ij.x_ij >= 0 needs with F < 0), and
  // at most Monaghan's value.
  for (int k = 1; k < 100; ++k) {
    const double vx = -delta * k / 100.0, p = smooth(vx, r2, hij, cbar, rhobar);
    CHECK(p >= 0.0);
    CHECK(p <= sharp(vx, r2, hij, cbar, rhobar));
  }
  // The sharp switch is linear in vx at 0 (a kink); the smooth one, vx P(-vx / delta) with P(t) ~ 1716 t^7
  // (core/polynomial_step.hpp), vanishes as vx^8: C^6 (C^7 at this end), where the C-infinity step of
  // core/smooth_step.hpp gave a ratio below 2^-20. (Pi is theta times a factor that tends to -alpha cbar.)
  const double a = -0.01 * delta, b = -0.02 * delta;
  CHECK(sharp(a, r2, hij, cbar, rhobar) / sharp(b, r2, hij, cbar, rhobar) == Approx(0.5).epsilon(0.01));
  CHECK(smooth(a, r2, hij, cbar, rhobar) / smooth(b, r2, hij, cbar, rhobar) == Approx(std::pow(2.0, -8)).epsilon(0.1));
}

TEMPLATE_TEST_CASE("smooth viscosity switch with an offset band: Monaghan outside it, dissipative in it, smooth at 0",
                   "[smooth_step][physics]", MonaghanPi, SignalVelocityPi) {
  const double r2 = 0.04, hij = 0.13, cbar = 3.0, rhobar = 1.2, width = 0.3, offset = 0.3;
  TestType sharp, shifted;
  if constexpr (std::is_same_v<TestType, MonaghanPi>) {
    sharp = MonaghanPi{1.0, 2.0, 0.1};
    shifted = MonaghanPi{1.0, 2.0, 0.1, width, offset};
  } else {
    sharp = SignalVelocityPi{1.0, 2.0};
    shifted = SignalVelocityPi{1.0, 2.0, width, offset};
  }
  const double delta = width * cbar * hij, lo = -(1 - offset) * delta, hi = offset * delta;
  // Outside the band [-(1 - offset) delta, offset delta]: Monaghan's Pi exactly (0 when receding).
  for (double vx : {-10.0, -1.0, lo * (1 + 1e-12), lo}) CHECK(shifted(vx, r2, hij, cbar, rhobar) == sharp(vx, r2, hij, cbar, rhobar));
  for (double vx : {hi, hi * (1 + 1e-12), 1.0}) CHECK(shifted(vx, r2, hij, cbar, rhobar) == 0.0);
  // In it: Pi of the sign that keeps the heating 1/2 m Pi F v_ij.x_ij >= 0 (F < 0): Pi >= 0 approaching,
  // Pi <= 0 receding; approaching, more than the band on the approaching side alone gives.
  TestType one_sided;
  if constexpr (std::is_same_v<TestType, MonaghanPi>) one_sided = MonaghanPi{1.0, 2.0, 0.1, width};
  else one_sided = SignalVelocityPi{1.0, 2.0, width};
  for (int k = 1; k < 100; ++k) {
    const double vx = lo + (hi - lo) * k / 100.0, p = shifted(vx, r2, hij, cbar, rhobar);
    CHECK(p * vx <= 0.0);
    if (vx < 0.0) {
      CHECK(p <= sharp(vx, r2, hij, cbar, rhobar));
      CHECK(p > one_sided(vx, r2, hij, cbar, rhobar));
    }
  }
  // Smooth through 0, where the sharp switch has its kink: the difference quotients of Pi on either side
  // of 0 agree (the sharp switch: 0 on the receding side).
  const double e = 1e-6 * delta;
  const double left = (shifted(0.0, r2, hij, cbar, rhobar) - shifted(-e, r2, hij, cbar, rhobar)) / e;
  const double right = (shifted(e, r2, hij, cbar, rhobar) - shifted(0.0, r2, hij, cbar, rhobar)) / e;
  CHECK(right == Approx(left).epsilon(1e-4));
  CHECK(left < 0.0);
  CHECK((sharp(e, r2, hij, cbar, rhobar) - sharp(0.0, r2, hij, cbar, rhobar)) / e == 0.0);
}
