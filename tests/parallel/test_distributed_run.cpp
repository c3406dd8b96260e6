// A run over ranks (parallel/mpi_run.hpp through run_case): the final state is the serial run's,
// bit for bit, on any rank count, for wall-particle scenes with both leapfrogs: the channel flows
// (summation density: two dependent pair passes, a two-radius halo; with particle shifting too),
// the dam break (continuity density with dynamic wall densities in the state; particles travel
// far enough to re-plan the halo many times) and the shock tube in 1D and 2D (the energy equation:
// e in the state, the walls' fixed e in each local system). Rank 0 runs the serial reference.
// Ghost walls: test_distributed_ghost.cpp; repulsive walls: test_distributed_repulsive.cpp; reordering:
// test_distributed_reorder.cpp.
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

TEST_CASE("distributed run: Poiseuille with the leapfrog equals the serial run bit for bit", "[parallel][run]") {
  check_same_as_serial(load_config(verification("poiseuille.yaml"),
                                   {"discretization.particles_across=20", "time.integrator=leapfrog", "time.t_end=0.03",
                                    "output.times=[0.01,0.03]", "output.plots=false"}));
}

TEST_CASE("distributed run: Couette with the kick-drift-kick leapfrog equals the serial run bit for bit", "[parallel][run]") {
  check_same_as_serial(load_config(verification("couette.yaml"),
                                   {"discretization.particles_across=20", "time.integrator=leapfrog_kdk", "time.t_end=0.03",
                                    "output.times=[0.03]", "output.plots=false"}));
}

TEST_CASE("distributed run: the dam break equals the serial run bit for bit, through many halo plans", "[parallel][run]") {
  const Config c = load_config(verification("dam_break.yaml"), {"discretization.spacing=0.04", "time.t_end=0.12",
                                                                "output.times=[0.06,0.12]", "output.plots=false"});
  SECTION("one partition") {
    const Finished split = check_same_as_serial(c);
    // The particles moved: the halo was planned again (with a new local system) during the run.
    CHECK(split.summary["parallel"]["halo_plans"].get<long>() > 3);
    CHECK(split.summary["parallel"]["halo_depth_list_radii"] == 1);
    CHECK(split.summary["parallel"]["terms_not_run"] == nlohmann::json::array());
    // Only rank 0 holds the whole scene's particles after the set-up; the others dropped theirs
    // before their first evaluation (SphSystem::release_particles).
    const auto held = split.summary["parallel"]["whole_scene_particles_held"].get<std::vector<std::uint64_t>>();
    const std::uint64_t n = split.summary["particles"]["fluid"].get<std::uint64_t>() + split.summary["particles"]["wall"].get<std::uint64_t>();
    REQUIRE(held.size() == static_cast<std::size_t>(Communicator().size()));
    CHECK(held[0] == n);
    for (std::size_t r = 1; r < held.size(); ++r) CHECK(held[r] == 0);
  }
  SECTION("partitioned again at every re-plan, the particles migrating with the leapfrog's state") {
    const Finished split = check_same_as_serial(c, 1.0);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 3);
  }
}

// The shock tube with the energy equation and constant h (the shipped tubes vary h): x ends closed by
// wall particles that keep their side's e, which enters their pressure (ideal gas).
namespace {
Config shock_tube(const std::string& file, std::vector<std::string> more = {}) {
  more.insert(more.begin(), "discretization.smoothing_length=constant");
  return short_shock_tube(file, more);
}
}  // namespace

TEST_CASE("distributed run: the 1D shock tube with the energy equation equals the serial run bit for bit", "[parallel][run][energy]") {
  const Config c = shock_tube("shock_tube_1d.yaml");
  REQUIRE(c.discretization.energy);
  SECTION("one partition") {
    const Finished split = check_same_as_serial(c);
    CHECK(split.summary["parallel"]["halo_plans"].get<long>() > 1);
  }
  SECTION("partitioned again at every re-plan, e migrating with the leapfrog's state") {
    const Finished split = check_same_as_serial(c, 1.0);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 0);
  }
}

TEST_CASE("distributed run: the 2D shock tube with the energy equation equals the serial run bit for bit", "[parallel][run][energy]") {
  // y periodic (wall particles at the x ends only), h0 = 1.0 dx to fit twice the pair radius across.
  check_same_as_serial(shock_tube("shock_tube.yaml", {"discretization.boundary=wall_particles",
                                                      "discretization.smoothing_ratio=1.0",
                                                      "time.integrator=leapfrog_kdk"}));
}

TEST_CASE("distributed run: the shipped shock tubes with variable h equal the serial run bit for bit", "[parallel][run][variable_h]") {
  // h in the state (dh/dt) or from the density: the local pair lists and the halo's reach follow the
  // largest h, which grows where the gas expands.
  SECTION("1D, equal masses (h(0) varies across the jump), h by dh/dt") {
    const Config c = short_shock_tube("sod_1d.yaml");
    REQUIRE(c.discretization.smoothing_length == "ode");
    check_same_as_serial(c);
  }
  SECTION("1D, h by dh/dt, repartitioned at every re-plan") {
    const Finished split = check_same_as_serial(short_shock_tube("shock_tube_1d.yaml"), 1.0);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 0);
  }
  SECTION("1D, h from the density") {
    check_same_as_serial(short_shock_tube("shock_tube_1d.yaml", {"discretization.smoothing_length=density"}));
  }
  SECTION("2D, h by dh/dt, y periodic") {
    check_same_as_serial(
        short_shock_tube("shock_tube.yaml", {"discretization.boundary=wall_particles", "discretization.smoothing_ratio=1.0"}));
  }
}

TEST_CASE("distributed run: particle shifting equals the serial run bit for bit", "[parallel][run][shifting]") {
  // The shift reads the summed densities of its neighbours (Poiseuille) or corrects the state's
  // density (Couette with continuity density), and scales its anti-clumping term by W(dx). With 19
  // particles across, h / smoothing_ratio is not the spacing to the bit (the local systems are
  // assembled with the scene's own).
  SECTION("summation density") {
    check_same_as_serial(load_config(verification("poiseuille.yaml"),
                                     {"discretization.particles_across=19", "geometry.channel_length=1.0e-3",
                                      "time.integrator=leapfrog", "time.t_end=0.03",
                                      "output.times=[0.01,0.03]", "output.plots=false",
                                      "discretization.particle_shifting={coefficient: 4}"}));
  }
  SECTION("continuity density") {
    check_same_as_serial(load_config(verification("couette.yaml"),
                                     {"discretization.particles_across=20", "time.integrator=leapfrog_kdk", "time.t_end=0.03",
                                      "output.times=[0.03]", "output.plots=false", "discretization.density=continuity",
                                      "discretization.particle_shifting={coefficient: 4}"}));
  }
}

TEST_CASE("distributed run: a 3D tank equals the serial run bit for bit", "[parallel][run]") {
  // Extrapolated wall pressures: a term over the stored pair list, which deepens the halo.
  check_same_as_serial(load_config(verification("hydrostatic_3d.yaml"),
                                   {"discretization.particles_across=8", "time.t_end=0.02", "output.times=[0.01,0.02]",
                                    "output.plots=false"}));
}

TEST_CASE("distributed run: a blow-up ends the run on every rank with one message", "[parallel][run]") {
  // A fixed step far above the acoustic limit: the dam break's particles leave the tank within a
  // few steps; every rank must stop at the same step with the same cause.
  const Communicator comm;
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.2);
  const Config c = load_config(verification("dam_break.yaml"), {"discretization.spacing=0.04", "time.t_end=0.5",
                                                                "time.dt=0.002", "output.times=[0.5]",
                                                                "output.plots=false"});
  const Finished split = run(c, &partitioner);
  REQUIRE(split.summary["status"] == "blown_up");
  const std::string message = split.summary["blow_up"]["message"].get<std::string>();
  const std::vector<char> all = comm.all_gather_v(std::vector<char>(message.begin(), message.end()));
  const std::vector<int> lengths = comm.all_gather(static_cast<int>(message.size()));
  std::size_t at = 0;
  for (int r = 0; r < comm.size(); ++r) {
    CHECK(std::string(all.begin() + static_cast<long>(at), all.begin() + static_cast<long>(at) + lengths[r]) == message);
    at += static_cast<std::size_t>(lengths[r]);
  }
  CHECK(split.summary["steps"].get<long>() > 0);
  CHECK(!split.summary["blow_up"].contains("state_file"));
}
