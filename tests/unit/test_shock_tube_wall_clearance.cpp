// The shock tube is measured against the exact solution of an infinite tube: the loader refuses a
// t_end past the time the outermost waves reach the end walls' particles, and states that move
// (which the walls at rest disturb from t = 0). The shipped tubes run well inside the limit.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "sphmol/cases/shock_tube/shock_tube_wall_clearance.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/reference/exact_riemann.hpp"

using namespace sphmol;
using Catch::Matchers::Contains;

namespace {

std::string tube(const std::string& name) { return std::string(SPHMOL_SOURCE_DIR) + "/verification/" + name + ".yaml"; }

std::string load_error(const std::string& name, const std::vector<std::string>& overrides) {
  try {
    (void)load_config(tube(name), overrides);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "<no error>";
}

}  // namespace

TEST_CASE("shock tube clearance: the time the outermost wave reaches an end wall's reach", "[shock_tube][config]") {
  // Sod (1978): shock speed 1.75216 (Toro 2009, §4.3.3, test 1), fan head -a_L = -sqrt(1.4).
  const ExactRiemannSolver sod({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 1.4);
  const ShockTubeClearance c = shock_tube_clearance(sod, 0.5, {0.01, 0.04});
  CHECK(c.side == 1);
  CHECK(c.shock);
  CHECK(c.speed == Approx(1.75216).epsilon(1e-5));
  CHECK(c.t_clear == Approx(0.46 / c.speed).epsilon(1e-12));
  CHECK(shock_tube_length_for(sod, c.t_clear, {0.01, 0.04}) == Approx(1.0).epsilon(1e-12));
  // Mirrored: the left end is reached first, by the shock.
  const ExactRiemannSolver mirrored({0.125, 0.0, 0.1}, {1.0, 0.0, 1.0}, 1.4);
  const ShockTubeClearance m = shock_tube_clearance(mirrored, 0.5, {0.04, 0.01});
  CHECK(m.side == 0);
  CHECK(m.shock);
  CHECK(m.t_clear == Approx(c.t_clear).epsilon(1e-12));
  // A tube shorter than the reach is never clear.
  CHECK(shock_tube_clearance(sod, 0.02, {0.01, 0.04}).t_clear < 0.0);
}

TEST_CASE("shock tube clearance: every shipped tube loads with its t_end", "[shock_tube][config]") {
  for (const char* name : {"shock_tube", "shock_tube_1d", "shock_tube_virtual", "sod", "sod_1d"}) {
    INFO(name);
    CHECK(load_error(name, {}) == "<no error>");
  }
}

TEST_CASE("shock tube clearance: a t_end past the walls' reach is refused with the largest one allowed", "[shock_tube][config]") {
  // The 1D Niedoba tube: shock 1.4847 m/s, the right end's reach (3 h + dx) = 0.01 m of the 0.4 m half:
  // clear until (0.4 - 0.01) / 1.4847 = 0.26267 s.
  const std::string e = load_error("shock_tube_1d", {"time.t_end=0.3", "output.times=[]"});
  CHECK_THAT(e, Contains("time.t_end: 0.3 s is past the time the waves reach the end walls"));
  CHECK_THAT(e, Contains("right-moving shock (1.484 m/s)"));
  CHECK_THAT(e, Contains("Give time.t_end <= 0.2626 s"));
  CHECK_THAT(e, Contains("geometry.tube_length >= 0.9125 m for this t_end"));
  // The numbers it names are allowed.
  CHECK(load_error("shock_tube_1d", {"time.t_end=0.2626", "output.times=[]"}) == "<no error>");
  CHECK(load_error("shock_tube_1d", {"time.t_end=0.3", "output.times=[]", "geometry.tube_length=0.9125"}) == "<no error>");
  CHECK(load_error("shock_tube_1d", {"time.t_end=0.2627", "output.times=[]"}) != "<no error>");
  // The mirrored Sod tube: the left end, reached by the shock.
  CHECK_THAT(load_error("sod_1d", {"time.t_end=0.3", "output.times=[]", "shock_tube.left={density: 0.125, pressure: 0.1}",
                                   "shock_tube.right={density: 1.0, pressure: 1.0}", "shock_tube.setup=equal_spacing"}),
             Contains("left-moving shock"));
  // 2D: the reach follows the end gas's h (1.3 dx) and spacing.
  CHECK_THAT(load_error("sod", {"time.t_end=0.3", "output.times=[]"}), Contains("Give time.t_end <= 0.2655 s"));
}

TEST_CASE("shock tube clearance: states moving along the tube are refused", "[shock_tube][config]") {
  for (const char* side : {"left", "right"}) {
    INFO(side);
    const std::string e = load_error("shock_tube_1d", {"time.t_end=0.1", "output.times=[]",
                                                       std::string("shock_tube.") + side + ".velocity=0.5"});
    CHECK_THAT(e, Contains(std::string("shock_tube.") + side + ".velocity: 0.5 m/s: the end walls are at rest"));
  }
  CHECK(load_error("shock_tube_1d", {"shock_tube.left.velocity=0"}) == "<no error>");
}
