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
    CHECK(std::abs(w.shock - xs) < 0.1 * dx + 0.02 * width);
    // The velocity crossing: ahead by about 0.37 widths (where rho has risen 0.32 of the jump,
    // tanh^-1(0.36) = 0.38), which the density crossing does not inherit.
    CHECK(w.shock_velocity - xs > 0.3 * width);
    CHECK(w.shock_velocity - xs < 0.45 * width + dx);
    // The other waves are the exact profile's.
    CHECK(std::isfinite(w.contact));
    CHECK(std::isfinite(w.rarefaction_head));
    CHECK(std::isfinite(w.rarefaction_tail));
  }
  // On the exact (sharp) profile both crossings are the shock.
  const ShockTubeWaves sharp = detect_waves(smeared_sod(ex, dx, 1e-9), ex);
  CHECK(std::abs(sharp.shock - xs) < dx);
  CHECK(std::abs(sharp.shock_velocity - xs) < dx);
}
