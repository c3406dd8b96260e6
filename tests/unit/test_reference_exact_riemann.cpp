// Exact Riemann solver (Toro ch. 4): published star states, Rankine-Hugoniot across shocks, isentropy
// and the Riemann invariant through rarefactions, Niedoba 2012, §3 shock tube.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "sphmol/reference/exact_riemann.hpp"

using sphmol::EulerState;
using sphmol::ExactRiemannSolver;
using sphmol::RiemannSample;

namespace {
constexpr double g14 = 1.4;

// Conserved fluxes relative to a frame moving with speed S: mass, momentum, energy (Toro eq 3.1 / 3.45).
struct Jump { double mass, mom, energy; };
Jump shock_frame_fluxes(const RiemannSample& s, double S) {
  const double w = s.u - S;
  return {s.rho * w, s.rho * w * w + s.p, s.rho * w * (s.e + 0.5 * w * w) + s.p * w};
}

void check_rankine_hugoniot(const ExactRiemannSolver& r, double S) {
  const double d = 1e-9 * std::max(1.0, std::abs(S));
  const RiemannSample a = r.sample(S - d), b = r.sample(S + d);
  REQUIRE(std::abs(a.rho - b.rho) > 1e-3 * std::max(a.rho, b.rho));  // really a jump
  const Jump ja = shock_frame_fluxes(a, S), jb = shock_frame_fluxes(b, S);
  const double scale_m = std::abs(a.rho * (a.u - S)) + std::abs(b.rho * (b.u - S));
  const double scale_p = ja.mom + jb.mom;
  const double scale_e = std::abs(ja.energy) + std::abs(jb.energy);
  CHECK(std::abs(ja.mass - jb.mass) <= 1e-13 * scale_m);
  CHECK(std::abs(ja.mom - jb.mom) <= 1e-13 * scale_p);
  CHECK(std::abs(ja.energy - jb.energy) <= 1e-13 * scale_e);
}
}  // namespace

TEST_CASE("Exact Riemann: Toro Table 4.3 star states", "[reference][riemann]") {
  struct Case { EulerState l, r; double p, u, rl, rr; };
  // Toro (2009) Table 4.3, tests 1-5, gamma = 1.4 (values printed to 5-6 significant digits).
  const Case cases[] = {
      {{1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 0.30313, 0.92745, 0.42632, 0.26557},
      {{1.0, -2.0, 0.4}, {1.0, 2.0, 0.4}, 0.00189, 0.0, 0.02185, 0.02185},
      {{1.0, 0.0, 1000.0}, {1.0, 0.0, 0.01}, 460.894, 19.5975, 0.57506, 5.99924},
      {{5.99924, 19.5975, 460.894}, {5.99242, -6.19633, 46.0950}, 1691.64, 8.68975, 14.2823, 31.0426},
  };
  for (const auto& c : cases) {
    const ExactRiemannSolver r(c.l, c.r, g14);
    INFO("pL = " << c.l.p << " pR = " << c.r.p);
    // Half a unit in the last printed digit.
    CHECK(r.p_star() == Approx(c.p).epsilon(6e-6).margin(6e-6));
    CHECK(r.u_star() == Approx(c.u).epsilon(6e-6).margin(6e-6));
    CHECK(r.rho_star_left() == Approx(c.rl).epsilon(6e-6).margin(6e-6));
    CHECK(r.rho_star_right() == Approx(c.rr).epsilon(6e-6).margin(6e-6));
  }
}

TEST_CASE("Exact Riemann: Sod wave structure, Rankine-Hugoniot, isentropy, Riemann invariant", "[reference][riemann]") {
  const EulerState L{1.0, 0.0, 1.0}, R{0.125, 0.0, 0.1};
  const ExactRiemannSolver r(L, R, g14);
  const auto w = r.wave_speeds();
  REQUIRE_FALSE(w.left_is_shock);
  REQUIRE(w.right_is_shock);
  CHECK(w.left_head == Approx(-std::sqrt(1.4)));  // head moves into the left state at -a_L
  CHECK(w.left_head < w.left_tail);
  CHECK(w.left_tail < w.contact);
  CHECK(w.contact < w.right_head);
  check_rankine_hugoniot(r, w.right_head);

  // Across the contact u and p are continuous, rho jumps.
  const RiemannSample cl = r.sample(w.contact - 1e-9), cr = r.sample(w.contact + 1e-9);
  CHECK(cl.p == cr.p);
  CHECK(cl.u == cr.u);
  CHECK(cl.rho == Approx(r.rho_star_left()).epsilon(1e-15));
  CHECK(cr.rho == Approx(r.rho_star_right()).epsilon(1e-15));

  // Through the left fan and into the left star region: p/rho^gamma and u + 2a/(gamma-1) constant, and the
  // fan is centred (u - a = xi).
  const double s_l = L.p / std::pow(L.rho, g14), j_l = L.u + 2.0 * std::sqrt(g14 * L.p / L.rho) / (g14 - 1.0);
  for (int i = 0; i <= 10; ++i) {
    const double xi = w.left_head + (w.contact - 1e-9 - w.left_head) * i / 10.0;
    const RiemannSample s = r.sample(xi);
    const double a = std::sqrt(g14 * s.p / s.rho);
    INFO("xi = " << xi);
    CHECK(s.p / std::pow(s.rho, g14) == Approx(s_l).epsilon(1e-13));
    CHECK(s.u + 2.0 * a / (g14 - 1.0) == Approx(j_l).epsilon(1e-13));
    if (xi > w.left_head && xi < w.left_tail) CHECK(s.u - a == Approx(xi).margin(1e-13));
    CHECK(s.e == Approx(s.p / ((g14 - 1.0) * s.rho)).epsilon(1e-15));
  }
  // Continuity of the fan at its tail (no jump into the star region).
  const RiemannSample t1 = r.sample(w.left_tail - 1e-12), t2 = r.sample(w.left_tail + 1e-12);
  CHECK(t1.rho == Approx(t2.rho).epsilon(1e-10));
  CHECK(t1.u == Approx(t2.u).epsilon(1e-10));
  // Far field returns the data.
  CHECK(r.sample(-10.0).rho == L.rho);
  CHECK(r.sample(10.0).p == R.p);
  CHECK(r.sample(0.3, 0.0, 0.5).rho == L.rho);
  CHECK(r.sample(0.5, 0.0, 0.5).rho == R.rho);
}

TEST_CASE("Exact Riemann: two shocks and a right rarefaction, RH and mirror symmetry", "[reference][riemann]") {
  // Toro test 4: two shocks.
  const ExactRiemannSolver r({5.99924, 19.5975, 460.894}, {5.99242, -6.19633, 46.0950}, g14);
  const auto w = r.wave_speeds();
  REQUIRE(w.left_is_shock);
  REQUIRE(w.right_is_shock);
  check_rankine_hugoniot(r, w.left_head);
  check_rankine_hugoniot(r, w.right_head);
  // Mirror of Sod: rarefaction on the right, shock on the left, solution reflected with u -> -u.
  const ExactRiemannSolver sod({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, g14);
  const ExactRiemannSolver mir({0.125, 0.0, 0.1}, {1.0, 0.0, 1.0}, g14);
  REQUIRE(mir.wave_speeds().left_is_shock);
  REQUIRE_FALSE(mir.wave_speeds().right_is_shock);
  for (double xi = -2.0; xi <= 2.0; xi += 0.0625) {
    const RiemannSample a = sod.sample(xi), b = mir.sample(-xi);
    if (std::abs(xi - sod.u_star()) < 1e-12) continue;
    INFO("xi = " << xi);
    CHECK(b.rho == Approx(a.rho).epsilon(1e-12));
    CHECK(b.p == Approx(a.p).epsilon(1e-12));
    CHECK(b.u == Approx(-a.u).epsilon(1e-12).margin(1e-14));
  }
}

TEST_CASE("Exact Riemann: vacuum generation and bad data are errors", "[reference][riemann]") {
  // 2(aL + aR)/(gamma - 1) = 2 * 2 * sqrt(1.4 * 0.4)/0.4 = 7.48 < uR - uL = 10.
  CHECK_THROWS_AS(ExactRiemannSolver({1.0, -5.0, 0.4}, {1.0, 5.0, 0.4}, g14), std::domain_error);
  CHECK_NOTHROW(ExactRiemannSolver({1.0, -3.0, 0.4}, {1.0, 3.0, 0.4}, g14));  // 6 < 7.48: near vacuum only
  CHECK_THROWS_AS(ExactRiemannSolver({0.0, 0.0, 1.0}, {1.0, 0.0, 1.0}, g14), std::invalid_argument);
  CHECK_THROWS_AS(ExactRiemannSolver({1.0, 0.0, 1.0}, {1.0, 0.0, -1.0}, g14), std::invalid_argument);
  CHECK_THROWS_AS(ExactRiemannSolver({1.0, 0.0, 1.0}, {1.0, 0.0, 1.0}, 1.0), std::invalid_argument);
}

TEST_CASE("Exact Riemann: Niedoba 2012, §3 shock tube gives a right-moving shock", "[reference][riemann]") {
  // Niedoba 2012, §3.2 (after Hernquist 1989): rho 1 / 0.25, p 1 / 0.1795, u = 0, gamma = 1.4; e_L = 2.5, e_R = 1.795.
  const ExactRiemannSolver r({1.0, 0.0, 1.0}, {0.25, 0.0, 0.1795}, g14);
  CHECK(r.sample(-5.0).e == Approx(2.5).epsilon(1e-15));
  CHECK(r.sample(5.0).e == Approx(1.795).epsilon(1e-15));
  const auto w = r.waves(0.2, 0.0);
  REQUIRE(w.right_is_shock);
  REQUIRE_FALSE(w.left_is_shock);
  CHECK(w.right_head > 0.0);
  CHECK(r.u_star() > 0.0);
  CHECK(r.p_star() > 0.1795);
  CHECK(r.p_star() < 1.0);
  check_rankine_hugoniot(r, r.wave_speeds().right_head);
  // Niedoba 2012, §3.4 reads off its figures at t = 0.2: shock near x = 0.3, rarefaction within [-0.3, 0],
  // contact between 0.1 and 0.2.
  CHECK(w.right_head == Approx(0.3).margin(0.03));
  CHECK(w.left_head >= -0.3);
  CHECK(w.left_tail <= 0.0);
  CHECK(w.contact > 0.1);
  CHECK(w.contact < 0.2);
}
