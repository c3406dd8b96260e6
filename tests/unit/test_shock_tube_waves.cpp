// The shock tube's wave detector (cases/shock_tube/shock_tube_case.hpp, detect_waves) on synthetic
// profiles: the exact Sod solution with its shock replaced by a steady smeared shock, the density a
// tanh step centred on the exact shock and the velocity from the mass flux across it,
// u = S (1 - rho_R / rho) (Rankine-Hugoniot in the shock's frame). The shock is read at the middle of
// its density jump, where it is; the velocity crossing u*/2 reads ahead by a fraction of the width.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "sphmol/cases/shock_tube/shock_tube_case.hpp"
#include "sphmol/reference/exact_riemann.hpp"

using namespace sphmol;

namespace {

// Sod (1978) at t = 0.2 on bins of width dx over [-0.5, 0.5], the shock smeared over `width`.
std::vector<ShockTubeBin> smeared_sod(const ExactRiemannSolver& ex, double dx, double width) {
  const double t = 0.2;
  const double xs = ex.waves(t, 0.0).right_head, S = ex.wave_speeds().right_head;
  const double rho_r = ex.right().rho, rho_s = ex.rho_star_right();
  std::vector<ShockTubeBin> bins;
  for (double x = -0.5 + 0.5 * dx; x < 0.5; x += dx) {
    RiemannSample q = ex.sample(x, t, 0.0);
    if (x > ex.waves(t, 0.0).contact + 0.05) {
      const double rho = rho_r + (rho_s - rho_r) * 0.5 * (1.0 - std::tanh((x - xs) / width));
      q.rho = rho;
      q.u = S * (1.0 - rho_r / rho);
    }
    bins.push_back({x, q.rho, q.u, q.p, q.e});
  }
  return bins;
}

}  // namespace

TEST_CASE("shock tube waves: a smeared steady shock is read at the middle of its density jump", "[shock_tube][waves]") {
  const ExactRiemannSolver ex({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 1.4);
  const double xs = ex.waves(0.2, 0.0).right_head;
  const double dx = 1e-3;
  for (const double width : {0.002, 0.005, 0.01}) {
    INFO("width " << width);
    const ShockTubeWaves w = detect_waves(smeared_sod(ex, dx, width), ex);
    // The density crossing: at the centre, to the linear interpolation's error.
    CHECK(std::abs(w.right.head - xs) < 0.1 * dx + 0.02 * width);
    // The velocity crossing: ahead by about 0.37 widths (where rho has risen 0.32 of the jump,
    // tanh^-1(0.36) = 0.38), which the density crossing does not inherit.
    CHECK(w.right.shock_velocity - xs > 0.3 * width);
    CHECK(w.right.shock_velocity - xs < 0.45 * width + dx);
    // The other waves are the exact profile's.
    CHECK(std::isfinite(w.contact));
    CHECK(std::isfinite(w.left.head));
    CHECK(std::isfinite(w.left.tail));
  }
  // On the exact (sharp) profile both crossings are the shock.
  const ShockTubeWaves sharp = detect_waves(smeared_sod(ex, dx, 1e-9), ex);
  CHECK(std::abs(sharp.right.head - xs) < dx);
  CHECK(std::abs(sharp.right.shock_velocity - xs) < dx);
}

namespace {

// The exact solution at t on bins of width dx over [-0.5, 0.5].
std::vector<ShockTubeBin> exact_profile(const ExactRiemannSolver& ex, double t, double dx) {
  std::vector<ShockTubeBin> bins;
  for (int k = 0; (k + 0.5) * dx < 1.0; ++k) {
    const double x = -0.5 + (k + 0.5) * dx;
    const RiemannSample q = ex.sample(x, t, 0.0);
    bins.push_back({x, q.rho, q.u, q.p, q.e});
  }
  return bins;
}

// Each wave of the exact pattern is found within a bin of its exact position (the fans' edges at
// their 5 % / 95 % crossings, which lie inside the fan: within the fan's width).
void check_on_exact(const ExactRiemannSolver& ex, double t, double dx) {
  const ShockTubeWaves w = detect_waves(exact_profile(ex, t, dx), ex);
  const RiemannWaves x = ex.waves(t, 0.0);
  CHECK(w.left.kind == (x.left_is_shock ? ShockTubeWaveKind::shock : ShockTubeWaveKind::rarefaction));
  CHECK(w.right.kind == (x.right_is_shock ? ShockTubeWaveKind::shock : ShockTubeWaveKind::rarefaction));
  // No density jump at the contact (the symmetric 123 problem): nothing to read.
  if (ex.rho_star_left() != ex.rho_star_right()) CHECK(std::abs(w.contact - x.contact) < dx);
  else CHECK(std::isnan(w.contact));
  const double fan_l = x.left_tail - x.left_head, fan_r = x.right_head - x.right_tail;
  CHECK(std::abs(w.left.head - x.left_head) < dx + 0.05 * fan_l);
  CHECK(std::abs(w.left.tail - x.left_tail) < dx + 0.05 * fan_l);
  CHECK(std::abs(w.right.head - x.right_head) < dx + 0.05 * fan_r);
  CHECK(std::abs(w.right.tail - x.right_tail) < dx + 0.05 * fan_r);
  if (x.left_is_shock) CHECK(std::abs(w.left.shock_velocity - x.left_head) < dx);
  if (x.right_is_shock) CHECK(std::abs(w.right.shock_velocity - x.right_head) < dx);
}

}  // namespace

TEST_CASE("shock tube waves: the mirrored Sod problem reads the mirrored waves", "[shock_tube][waves]") {
  const ExactRiemannSolver sod({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 1.4);
  const ExactRiemannSolver mirrored({0.125, 0.0, 0.1}, {1.0, 0.0, 1.0}, 1.4);
  const double dx = 1e-3;
  check_on_exact(sod, 0.2, dx);
  check_on_exact(mirrored, 0.2, dx);
  // A smeared shock, mirrored bin by bin: every position negated.
  const std::vector<ShockTubeBin> bins = smeared_sod(sod, dx, 0.005);
  std::vector<ShockTubeBin> m(bins.rbegin(), bins.rend());
  for (auto& b : m) {
    b.x = -b.x;
    b.u = -b.u;
  }
  const ShockTubeWaves a = detect_waves(bins, sod), b = detect_waves(m, mirrored);
  CHECK(b.left.kind == ShockTubeWaveKind::shock);
  CHECK(b.right.kind == ShockTubeWaveKind::rarefaction);
  CHECK(b.left.head == Approx(-a.right.head).margin(1e-12));
  CHECK(b.left.shock_velocity == Approx(-a.right.shock_velocity).margin(1e-12));
  CHECK(b.right.head == Approx(-a.left.head).margin(1e-12));
  CHECK(b.right.tail == Approx(-a.left.tail).margin(1e-12));
  CHECK(b.contact == Approx(-a.contact).margin(1e-12));
}

TEST_CASE("shock tube waves: two shocks and two rarefactions are read as such", "[shock_tube][waves]") {
  // Colliding streams (two shocks; Toro 2009, §4.3.3, test 5 scaled) and the 123 problem (two
  // rarefactions, test 2), at times that keep the waves inside [-0.5, 0.5].
  const ExactRiemannSolver two_shocks({1.0, 1.0, 1.0}, {0.5, -1.0, 0.2}, 1.4);
  const ExactRiemannSolver two_fans({1.0, -2.0, 0.4}, {1.0, 2.0, 0.4}, 1.4);
  REQUIRE(shock_tube_wave_kind(two_shocks, 0) == ShockTubeWaveKind::shock);
  REQUIRE(shock_tube_wave_kind(two_shocks, 1) == ShockTubeWaveKind::shock);
  REQUIRE(shock_tube_wave_kind(two_fans, 0) == ShockTubeWaveKind::rarefaction);
  REQUIRE(shock_tube_wave_kind(two_fans, 1) == ShockTubeWaveKind::rarefaction);
  check_on_exact(two_shocks, 0.15, 1e-3);
  check_on_exact(two_fans, 0.1, 1e-3);
}

TEST_CASE("shock tube waves: equal pressures leave only the contact", "[shock_tube][waves]") {
  const ExactRiemannSolver ex({1.0, 0.0, 1.0}, {0.25, 0.0, 1.0}, 1.4);
  const ShockTubeWaves w = detect_waves(exact_profile(ex, 0.2, 1e-3), ex);
  CHECK(w.left.kind == ShockTubeWaveKind::none);
  CHECK(w.right.kind == ShockTubeWaveKind::none);
  CHECK(std::isnan(w.left.head));
  CHECK(std::abs(w.contact) < 1e-3);
}
