// The viscous step limit over ranks: 0.125 h^2 / nu of the most viscous fluid of the whole scene on
// every rank, whichever liquids a rank holds. A rank holding only the thin liquid (or walls alone)
// must not step at its own, wider, limit: the ranks would then take different steps. Rank 0 runs
// the serial reference.
#include <catch2/catch.hpp>

#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "serial_reference.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
using namespace sphmol::parallel::testing;

namespace {

// A shallow layer of a viscous liquid (nu = 0.5 m^2/s) under a deep one of a thin liquid (1e-6 m^2/s)
// in a tall tank, periodic in x, the thin liquid sheared: the partition cuts across the height, and
// the ranks above the cut hold no viscous particle, not even in their halo. At this spacing the thick liquid's viscous limit (0.125 h^2 / nu = 5.6e-5 s) is
// below the acoustic one (0.25 h / c = 1.9e-4 s), the thin liquid's far above it.
Config layered_liquids() {
  return load_config_string(R"yaml(case: scene
dimension: 2
fluid:
  density: 1000.0
  kinematic_viscosity: 1.0e-6
  eos: {type: tait, sound_speed: 20.0, gamma: 7.0, clamp_negative: true}
  body_force: [0.0, -9.81]
scene:
  domain: {lo: [0, 0], hi: [0.2, 0.6], boundaries: [periodic, wall]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [0.2, 0.1]}
      kinematic_viscosity: 0.5
      pressure: hydrostatic
    - shape: {type: box, lo: [0, 0.1], hi: [0.2, 0.5]}
      density: 800
      pressure: hydrostatic
      velocity: ["0.2", "0"]
discretization:
  spacing: 0.01
  kernel: wendland_c2
  smoothing_ratio: 1.5
  density: continuity
  viscosity: morris
time: {t_end: 0.01, integrator: leapfrog}
output: {times: [0.005, 0.01], plots: false, profiles: false}
)yaml");
}

}  // namespace

TEST_CASE("distributed run: two liquids of different viscosity step at the whole scene's viscous limit",
          "[parallel][run][viscous_limit]") {
  const Config c = layered_liquids();
  const Finished split = check_same_as_serial(c);
  if (Communicator().rank() == 0) {
    // The viscous limit binds: 0.01 s in steps of 0.125 h^2 / 0.5 = 5.6e-5 s at most.
    CHECK(split.summary["steps"].get<long>() >= 170);
  }
}
