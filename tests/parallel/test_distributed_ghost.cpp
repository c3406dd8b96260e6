// Ghost (mirror) walls over ranks (parallel/distributed_system.hpp): every rank's local system
// mirrors its own fluid particles, owned and halo, so an owned particle's images come from its halo
// sources, in the serial order, with their sources' fields computed there as on their owners. The
// final state, the steps and the RHS evaluations are the serial run's to the bit on any rank count:
// the 2D Sod tube (free-slip walls along the tube, which every cut crosses; h by dh/dt, so the images
// follow a growing support), the lid-driven cavity (no-slip walls, a moving lid, corner images) and a
// water column (images under gravity carry a hydrostatic pressure; summation density: a two-radius
// halo whose outer rows need their own images). Rank 0 runs the serial reference.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/mpi_run.hpp"
#include "sphmol/run/run_case.hpp"
#include "serial_reference.hpp"
#include "short_shock_tube.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
using namespace sphmol::parallel::testing;

namespace {

// The mirror walls are what this file is about.
Finished check_ghost_same_as_serial(const Config& c, const std::vector<std::string>& output_only = {}, double rebalance = 1.2) {
  REQUIRE(c.discretization.boundary == "ghost");
  return check_same_as_serial(c, output_only, rebalance);
}

Config cavity(const std::string& integrator) {
  return load_config(verification("cavity.yaml"),
                     {"discretization.boundary=ghost", "discretization.wall_model=prescribed", "discretization.particles_across=20",
                      "time.integrator=" + integrator, "time.t_end=0.1", "output.times=[0.05,0.1]", "output.plots=false"});
}

}  // namespace

TEST_CASE("distributed run: the 2D Sod tube with free-slip ghost walls equals the serial run bit for bit", "[parallel][run][ghost]") {
  SECTION("leapfrog, one partition") {
    const Config c = short_shock_tube("sod.yaml");
    REQUIRE(c.discretization.smoothing_length == "ode");
    const Finished split = check_ghost_same_as_serial(c);
    CHECK(split.summary["parallel"]["halo_plans"].get<long>() > 1);
  }
  SECTION("leapfrog, partitioned again at every re-plan") {
    const Finished split = check_ghost_same_as_serial(short_shock_tube("sod.yaml"), {}, 1.0);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 0);
  }
  SECTION("cvode_adams") { check_ghost_same_as_serial(short_shock_tube("sod.yaml", {"time.integrator=cvode_adams"})); }
}

TEST_CASE("distributed run: the lid-driven cavity with no-slip ghost walls equals the serial run bit for bit",
          "[parallel][run][ghost]") {
  // Four no-slip mirrors: the lid's images move at 2 U - v, the corners' particles have three images.
  SECTION("leapfrog, one partition") { check_ghost_same_as_serial(cavity("leapfrog")); }
  SECTION("leapfrog, partitioned again at every re-plan") {
    const Finished split = check_ghost_same_as_serial(cavity("leapfrog"), {}, 1.0);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 0);
  }
  SECTION("arkode_erk") { check_ghost_same_as_serial(cavity("arkode_erk")); }
}

TEST_CASE("distributed run: a water column with ghost walls under gravity equals the serial run bit for bit",
          "[parallel][run][ghost]") {
  // Summation density (two dependent passes: the halo reaches two list radii) with the bottom and side
  // mirrors, whose images carry p_i + rho_i g.(x_g - x_i).
  const Config c = load_config(verification("hydrostatic.yaml"),
                               {"discretization.boundary=ghost", "discretization.wall_pressure=rest",
                                "discretization.kernel=cubic_spline", "discretization.smoothing_ratio=1.3",
                                "discretization.density=summation", "fluid.eos.clamp_negative=true",
                                "discretization.particles_across=20", "time.dt=5.0e-4", "time.t_end=0.05",
                                "output.times=[0.025,0.05]", "output.plots=false"});
  const Finished split = check_ghost_same_as_serial(c, {"max_drift", "drift_creep", "drift_creep_since"});
  CHECK(split.summary["parallel"]["halo_depth_list_radii"].get<int>() >= 2);
}

TEST_CASE("distributed run: a water column that falls through its bottom mirror equals the serial run bit for bit",
          "[parallel][run][ghost]") {
  // Gravity of 100 m/s^2 switched on at once: the column slams into its bottom mirror and particles
  // pass behind it (y < 0 from t = 0.25 s on; the halo's mirror margin is reported, > 0). A particle
  // behind a mirror has images of its neighbours nearer than the neighbours themselves, and its own
  // images lie in front of the mirror. (Setting the margin to zero does not change this run: no pair
  // fell in the band the margin adds while it crossed a rank boundary.)
  const Config c = load_config(verification("hydrostatic.yaml"),
                               {"discretization.boundary=ghost", "discretization.wall_pressure=rest",
                                "discretization.kernel=cubic_spline", "discretization.smoothing_ratio=1.3",
                                "discretization.density=continuity", "fluid.eos.clamp_negative=true",
                                "geometry.box=[0.25, 0.6]", "discretization.particles_across=5", "time.dt=2.5e-4", "time.t_end=0.3",
                                "discretization.skin=0.1", "fluid.body_force=[0, -100]", "fluid.body_force_ramp=0",
                                "output.times=[0.15,0.3]", "output.plots=false"});
  const Finished split = check_ghost_same_as_serial(c, {"max_drift", "drift_creep", "drift_creep_since"});
  CHECK(split.summary["parallel"]["ghost_mirror_margin_max"].get<double>() > 0.0);
}
