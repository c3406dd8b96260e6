// Repulsive walls over ranks (boundary/repulsive_force.hpp): the final state, steps and measurements
// are the serial run's, bit for bit, on any rank count. The repulsive force sums over each fluid
// row's wall neighbours in the stored pair list, so the halo is one list radius deeper than the pair
// passes alone ask for; the per-body laws of a scene's repulsive bodies are among the per-body tables
// every rank keeps whole. Rank 0 runs the serial reference.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "serial_reference.hpp"
#include "short_shock_tube.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
using namespace sphmol::parallel::testing;

namespace {
// The run's terms include the repulsive force (the local systems' terms, over ranks).
bool runs_term(const Finished& f, const std::string& name) {
  for (const auto& t : f.summary["active_terms"])
    if (t == name) return true;
  return false;
}
}  // namespace

TEST_CASE("distributed run: the 2D shock tube with virtual repulsive walls equals the serial run bit for bit",
          "[parallel][run][repulsive]") {
  // Virtual particles of mass rho dx^2 on y = -dx and y = W + dx, in every SPH sum and pushing by
  // eq 2.76 of Niedoba 2012; the energy equation and h by dh/dt, as shipped.
  const Config c = short_shock_tube("shock_tube_virtual.yaml");
  REQUIRE(c.discretization.boundary == "virtual_repulsive");
  SECTION("one partition") {
    const Finished split = check_same_as_serial(c);
    CHECK(runs_term(split, "repulsive_boundary"));
    if (Communicator().rank() == 0) {
      CHECK(split.summary["parallel"]["halo_plans"].get<long>() > 2);
      CHECK(split.summary["parallel"]["terms_not_run"] == nlohmann::json::array());
    }
  }
  SECTION("partitioned again at every re-plan, the particles migrating with the leapfrog's state") {
    const Finished split = check_same_as_serial(c, 1.0);
    if (Communicator().size() > 1 && Communicator().rank() == 0)
      CHECK(split.summary["parallel"]["repartitions"].get<long>() > 1);
  }
}

TEST_CASE("distributed run: the 2D tank with massless virtual repulsive walls equals the serial run bit for bit",
          "[parallel][run][repulsive]") {
  // The box case's virtual walls (scenes/box_scene.cpp): massless, acting by the repulsive force alone,
  // with the settings of the integration test (tests/integration/test_walls.cpp), run for 0.1 s.
  const Config c = load_config(verification("hydrostatic.yaml"),
                               {"discretization.boundary=virtual_repulsive", "discretization.wall_pressure=rest",
                                "discretization.repulsive.strength=8.8", "discretization.repulsive.r0=0.5",
                                "discretization.density=continuity", "discretization.particle_mass=summation",
                                "discretization.kernel=cubic_spline", "discretization.smoothing_ratio=1.3",
                                "fluid.eos.clamp_negative=true", "discretization.particles_across=20", "time.dt=5e-4",
                                "fluid.eos.sound_speed=29.7", "time.t_end=0.1", "output.times=[0.05, 0.1]",
                                "output.plots=false"});
  const Finished split = check_same_as_serial(c);
  CHECK(runs_term(split, "repulsive_boundary"));
}

namespace {

// A column of water 0.1 m wide and 0.2 m high collapsing in a closed tank 0.4 m wide onto two
// repulsive blocks on the floor with laws of their own (the second one's strength from the scene's
// velocity scale) and a dynamic block between them: the front runs through the blocks' force fields,
// and the particles move far enough for the halo to be planned many times.
Config tank_with_repulsive_blocks() {
  return load_config_string(R"yaml(case: scene
dimension: 2
fluid:
  density: 1000.0
  kinematic_viscosity: 1.0e-6
  eos: {type: tait, sound_speed: 20.0, gamma: 7.0, clamp_negative: true}
  body_force: [0.0, -9.81]
scene:
  domain: {lo: [0, 0], hi: [0.4, 0.3], boundaries: [wall, wall]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [0.1, 0.2]}
      pressure: hydrostatic
  walls:
    - name: near
      shape: {type: box, lo: [0.15, 0], hi: [0.18, 0.03]}
      treatment: repulsive
      repulsive: {strength: 4.0, p1: 12.0, p2: 4.0, r0: 0.8}
    - name: middle
      shape: {type: box, lo: [0.24, 0], hi: [0.27, 0.03]}
      treatment: dynamic
    - name: far
      shape: {type: sphere, centre: [0.33, 0.03], radius: 0.02}
      treatment: repulsive
discretization:
  spacing: 0.01
  kernel: wendland_c2
  smoothing_ratio: 1.5
  density: continuity
  artificial_viscosity: {alpha: 0.1}
time: {t_end: 0.2, integrator: leapfrog}
output: {times: [0.1, 0.2], plots: false, profiles: false}
)yaml");
}

}  // namespace

TEST_CASE("distributed run: a scene with repulsive wall bodies equals the serial run bit for bit", "[parallel][run][repulsive]") {
  const Config c = tank_with_repulsive_blocks();
  SECTION("one partition") {
    const Finished split = check_same_as_serial(c);
    CHECK(runs_term(split, "repulsive_bodies"));
    if (Communicator().rank() == 0) CHECK(split.summary["parallel"]["halo_plans"].get<long>() > 3);
  }
  SECTION("partitioned again at every re-plan") {
    const Finished split = check_same_as_serial(c, 1.0);
    if (Communicator().size() > 1 && Communicator().rank() == 0)
      CHECK(split.summary["parallel"]["repartitions"].get<long>() > 1);
  }
}
