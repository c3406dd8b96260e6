// Reordering over ranks (discretization.reorder: true): the serial run sorts its workspace along a
// Morton curve at every rebuild of its neighbour list (neighbors/particle_reorder.hpp), and each
// local system keeps its particles in that order (parallel/distributed_system.hpp). The final state,
// steps and measurements equal the serial reordered run's bit for bit on any rank count. Rank 0
// runs the serial reference.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "serial_reference.hpp"
#include "short_shock_tube.hpp"
#include "shot_scene.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
using namespace sphmol::parallel::testing;

namespace {
// check_same_as_serial, and the ranks took the serial workspace order at each of the serial list's
// rebuilds (at least `sorts` of them: the first evaluation's and those the particles' motion causes),
// no more and no fewer.
Finished check_reordered(const Config& c, double rebalance = 1.2, long evaluations_per_start = 1, long sorts = 2) {
  REQUIRE(c.discretization.reorder);
  const Finished split = check_same_as_serial(c, rebalance, evaluations_per_start);
  if (Communicator().rank() == 0) {
    const long rebuilds = serial_run(c).summary["neighbor_rebuilds"].get<long>();
    CHECK(rebuilds >= sorts);
    CHECK(split.summary["parallel"]["reorder_serial_list_rebuilds"].get<long>() == rebuilds);
  }
  return split;
}
}  // namespace

TEST_CASE("distributed run: the reordered dam break equals the serial reordered run bit for bit", "[parallel][run][reorder]") {
  // The particles travel far: the serial list is rebuilt (and the workspace sorted again) many times.
  const Config c = load_config(verification("dam_break.yaml"), {"discretization.spacing=0.04", "time.t_end=0.12",
                                                                "output.times=[0.06,0.12]", "output.plots=false",
                                                                "discretization.reorder=true"});
  SECTION("one partition") {
    const Finished split = check_reordered(c);
    CHECK(split.summary["parallel"]["halo_plans"].get<long>() > 3);
  }
  SECTION("partitioned again at every re-plan, the particles migrating with their sorting positions") {
    const Finished split = check_reordered(c, 1.0);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 3);
  }
}

TEST_CASE("distributed run: reordered Poiseuille (periodic) equals the serial reordered run bit for bit", "[parallel][run][reorder]") {
  // Summation density (two dependent passes) and a periodic x axis: positions wrap into the box
  // before they are sorted, on every rank as serially.
  check_reordered(load_config(verification("poiseuille.yaml"),
                              {"discretization.particles_across=20", "time.integrator=leapfrog", "time.t_end=0.03",
                               "output.times=[0.01,0.03]", "output.plots=false", "discretization.reorder=true"}),
                  1.2, 1, 1);
}

TEST_CASE("distributed run: the reordered shock tubes with variable h equal the serial reordered run bit for bit",
          "[parallel][run][reorder][variable_h]") {
  // The serial list's support follows the largest h: its growth since the rebuild eats into the skin.
  SECTION("1D, h by dh/dt") {
    check_reordered(short_shock_tube("shock_tube_1d.yaml", {"discretization.reorder=true"}), 1.0);
  }
  SECTION("1D, h from the density") {
    check_reordered(
        short_shock_tube("shock_tube_1d.yaml", {"discretization.smoothing_length=density", "discretization.reorder=true"}));
  }
  SECTION("2D, virtual repulsive walls") {
    check_reordered(short_shock_tube("shock_tube_virtual.yaml", {"discretization.reorder=true"}));
  }
}

TEST_CASE("distributed run: reordered runs with the IMEX integrators equal the serial reordered run bit for bit",
          "[parallel][run][reorder][imex]") {
  // The viscous operator's rows list their entries in the local row order, the serial workspace's.
  for (const std::string integrator : {"leapfrog_imex", "arkode_imex"}) {
    DYNAMIC_SECTION(integrator) {
      check_reordered(load_config(verification("couette.yaml"),
                                  {"discretization.particles_across=20", "time.integrator=" + integrator,
                                   "time.t_end=0.03", "output.times=[0.03]", "output.plots=false",
                                   "discretization.reorder=true"}),
                      1.2, integrator == "leapfrog_imex" ? 2 : 1, 1);
    }
  }
}

TEST_CASE("distributed run: a reordered run with fluid leaving through an open face equals the serial one bit for bit",
          "[parallel][run][reorder][outflow]") {
  // Fluid taken out of the run makes the serial list be rebuilt (and the workspace sorted) at the next
  // evaluation (SphSystem::retire), which moves the later rebuilds; the block falls under gravity
  // meanwhile, so that they sort it anew.
  const Finished split = check_reordered(sphmol::testing::shot_scene(
      {"time.t_end=0.06", "output.times=[0.03, 0.06]", "fluid.body_force=[0.0, -9.81]", "discretization.reorder=true"}));
  if (Communicator().rank() == 0) CHECK(split.summary["outflow"]["particles"] == 1);
}
