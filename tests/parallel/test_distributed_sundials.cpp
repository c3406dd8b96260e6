// ARKODE (ERKStep) and CVODE (Adams) over ranks (parallel/mpi_run.hpp through run_case): the state
// is an MPI vector over the ranks' owned rows whose weighted RMS norm is a fixed-point sum that does
// not depend on the order of additions (parallel/fixed_point_norm_mpi.hpp), so the steps, the RHS evaluations and the final state are the
// serial run's to the bit on any rank count. The dam break tells: its adaptive steps amplify a norm
// rounded otherwise (the MPI vector's own per-rank partial sums) into another step sequence within
// 0.01 s, and the states then differ at the tolerance's level (about 1e-5 relative). Rank 0 runs
// the serial reference.
// The IMEX integrators (arkode_imex, leapfrog_imex) over ranks likewise: their stage solves apply the
// owned rows' viscous operator with halo velocities fetched from their owners, and their Krylov dot
// products are exact sums reduced over the ranks (time/fixed_point_norm.hpp), so the Krylov
// iterations, steps and states are the serial run's to the bit.
#include <catch2/catch.hpp>
#include <unistd.h>

#include <filesystem>
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
namespace fs = std::filesystem;

namespace {


Config channel(const std::string& file, const std::string& integrator, const std::vector<std::string>& more = {}) {
  std::vector<std::string> o{"discretization.particles_across=20", "time.integrator=" + integrator, "time.t_end=0.03",
                             "output.times=[0.01,0.03]", "output.plots=false"};
  o.insert(o.end(), more.begin(), more.end());
  return load_config(verification(file), o);
}

Config dam_break(const std::string& integrator, const std::vector<std::string>& more = {}) {
  std::vector<std::string> o{"discretization.spacing=0.04", "time.integrator=" + integrator, "time.t_end=0.04",
                             "output.times=[0.02,0.04]", "output.plots=false"};
  o.insert(o.end(), more.begin(), more.end());
  return load_config(verification("dam_break.yaml"), o);
}

}  // namespace

TEST_CASE("distributed run: Poiseuille with ARKODE equals the serial run bit for bit", "[parallel][run][sundials]") {
  SECTION("the default table (Dormand-Prince)") { check_same_as_serial(channel("poiseuille.yaml", "arkode_erk"), 1.2, 0); }
  SECTION("a named table") {
    check_same_as_serial(channel("poiseuille.yaml", "arkode_erk", {"time.table=ARKODE_BOGACKI_SHAMPINE_4_2_3"}), 1.2, 0);
  }
}

TEST_CASE("distributed run: Couette with CVODE Adams equals the serial run bit for bit", "[parallel][run][sundials]") {
  check_same_as_serial(channel("couette.yaml", "cvode_adams"), 1.2, 0);
}

TEST_CASE("distributed run: the dam break with ARKODE and CVODE equals the serial run bit for bit",
          "[parallel][run][sundials]") {
  SECTION("arkode_erk") {
    const Finished split = check_same_as_serial(dam_break("arkode_erk"), 1.2, 0);
    // Stage states at which the halo had to be planned again: the particles moved.
    CHECK(split.summary["parallel"]["halo_plans"].get<long>() > 1);
  }
  SECTION("cvode_adams") { check_same_as_serial(dam_break("cvode_adams"), 1.2, 0); }
}

TEST_CASE("distributed run: the 1D shock tube with the energy equation, ARKODE and CVODE equals the serial run bit for bit",
          "[parallel][run][sundials][energy]") {
  // e (and h) in the state and in the error norm.
  SECTION("arkode_erk, constant h") {
    check_same_as_serial(
        short_shock_tube("shock_tube_1d.yaml", {"discretization.smoothing_length=constant", "time.integrator=arkode_erk"}), 1.2, 0);
  }
  SECTION("cvode_adams, the shipped Sod tube (h by dh/dt)") {
    check_same_as_serial(short_shock_tube("sod_1d.yaml", {"time.integrator=cvode_adams"}), 1.2, 0);
  }
}

TEST_CASE("distributed run: Poiseuille and Couette with the IMEX integrators equal the serial run bit for bit",
          "[parallel][run][sundials][imex]") {
  for (const std::string file : {"poiseuille.yaml", "couette.yaml"}) {
    SECTION(file + ", arkode_imex") {
      const Finished split = check_same_as_serial(channel(file, "arkode_imex"));
      CHECK(split.summary["integrator"]["krylov_iterations"].get<long>() > 0);
    }
    SECTION(file + ", arkode_imex with GMRES and a named table") {
      check_same_as_serial(channel(file, "arkode_imex", {"time.krylov.solver=spgmr", "time.table=ARKODE_ARK436L2SA_ERK_6_3_4"}));
    }
    SECTION(file + ", leapfrog_imex") {
      // Over ten steps at the shipped acoustic coefficient.
      const Finished split = check_same_as_serial(channel(file, "leapfrog_imex", {"time.t_end=0.1", "output.times=[0.05,0.1]"}));
      CHECK(split.summary["integrator"]["krylov_iterations"].get<long>() > 0);
    }
  }
}

TEST_CASE("distributed run: arkode_imex's frozen operator across halo plans equals the serial run bit for bit",
          "[parallel][run][sundials][imex]") {
  // Couette until the fluid by the moving plate has moved half the skin: stage evaluations plan the
  // halo again while L_n, recorded with the previous plan, is still applied.
  const Finished split = check_same_as_serial(channel("couette.yaml", "arkode_imex", {"time.t_end=0.6", "output.times=[0.3,0.6]"}));
  CHECK(split.summary["parallel"]["halo_plans"].get<long>() > 1);
}

TEST_CASE("distributed run: leapfrog_imex repartitioned over ranks equals the serial run bit for bit",
          "[parallel][run][imex][repartition]") {
  // A threshold of 1 asks for a new partition at every re-plan. The particles migrate with
  // leapfrog_imex's carried arrays (f, c, the previous velocities and f_I = L v + b of the operator
  // recorded at the step's predicted state), and the steps go on as in the serial run.
  SECTION("Poiseuille, partitioned again at every step") {
    // 21 x 11 fluid particles: no cut splits the pair work evenly on 2 ranks (20 x 10 would, and the
    // imbalance would stay 1), so every re-plan repartitions, and every repartition plans again.
    const Finished split = check_same_as_serial(channel("poiseuille.yaml", "leapfrog_imex",
                                                        {"discretization.particles_across=21", "geometry.channel_length=5.238095238095238e-4",
                                                         "time.t_end=0.6", "output.times=[0.3,0.6]"}),
                                                1.0, 2);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 10);
    // The counters carried through each start on a new share are not counted twice: one solve per step.
    CHECK(split.summary["integrator"]["implicit_solves"] == split.summary["steps"]);
  }
  SECTION("the lid-driven cavity stirs the particles: repartitioned again and again") {
    const Config c = load_config(verification("cavity.yaml"), {"discretization.particles_across=20", "time.integrator=leapfrog_imex",
                                                               "time.t_end=0.5", "output.times=[0.25,0.5]", "output.plots=false"});
    const Finished split = check_same_as_serial(c, 1.0, 2);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 1);
  }
}

TEST_CASE("distributed run: ARKODE repartitioned over ranks equals the serial run bit for bit",
          "[parallel][run][sundials][repartition]") {
  // A threshold of 1 asks for a new partition at every re-plan. ERKStep's vectors (its last f, the
  // stages, the interpolation history) move with the particles; it keeps its step size and error
  // history, and evaluates nothing more.
  SECTION("the dam break, Dormand-Prince (first stage reused from the last)") {
    const Finished split = check_same_as_serial(dam_break("arkode_erk"), 1.0, 0);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 0);
  }
  SECTION("the dam break, Verner 8(5)6 (no reused stage)") {
    const Finished split = check_same_as_serial(dam_break("arkode_erk", {"time.table=ARKODE_VERNER_8_5_6"}), 1.0, 0);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 0);
  }
}

TEST_CASE("distributed run: CVODE repartitioned over ranks equals the serial run bit for bit",
          "[parallel][run][sundials][repartition]") {
  // A threshold of 1 asks for a new partition at every re-plan. The Nordsieck history and every other
  // vector CVODE keeps move with the particles (parallel/vector_family.hpp): CVODE goes on with its
  // order and step as in the serial run, without a further evaluation.
  const Finished split = check_same_as_serial(dam_break("cvode_adams"), 1.0, 0);
  if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 1);
}

TEST_CASE("distributed run: arkode_imex repartitioned over ranks equals the serial run bit for bit",
          "[parallel][run][sundials][imex][repartition]") {
  // A threshold of 1 asks for a new partition at every re-plan. ARKStep's vectors (its stages and the
  // interpolation history its stage predictor reads) move with the particles; the frozen operator L_n
  // is recorded again on the new share at y_n, one evaluation per repartition.
  SECTION("Poiseuille") {
    // 21 x 11 fluid particles: no cut splits the pair work evenly on 2 ranks.
    const Finished split = check_same_as_serial(channel("poiseuille.yaml", "arkode_imex",
                                                        {"discretization.particles_across=21", "geometry.channel_length=5.238095238095238e-4",
                                                         "time.t_end=0.6", "output.times=[0.3,0.6]"}),
                                                1.0, 1);
    CHECK(split.summary["integrator"]["krylov_iterations"].get<long>() > 0);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 1);
  }
  SECTION("the lid-driven cavity stirs the particles") {
    const Config c = load_config(verification("cavity.yaml"), {"discretization.particles_across=20", "time.integrator=arkode_imex",
                                                               "time.t_end=0.5", "output.times=[0.25,0.5]", "output.plots=false"});
    const Finished split = check_same_as_serial(c, 1.0, 1);
    CHECK(split.summary["integrator"]["krylov_iterations"].get<long>() > 0);
    if (Communicator().size() > 1) CHECK(split.summary["parallel"]["repartitions"].get<long>() > 1);
  }
}

// A checkpoint of c written over ranks at `checkpoint` (its folder name), continued over ranks, ends
// where the serial run's checkpoint continued serially ends: the same steps and RHS evaluations and
// the same state to the bit.
static void check_restart_same_as_serial(const Config& c, const std::string& name, const std::string& checkpoint) {
  const Communicator comm;
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.2);
  // One folder for all ranks (rank 0 writes, every rank reads the checkpoint), one per rank count.
  const long pid = comm.all_gather(static_cast<long>(::getpid()))[0];
  const fs::path dir = fs::temp_directory_path() / ("sphmol-" + name + "-restart-" + std::to_string(pid) + "-" + std::to_string(comm.size()));
  run(c, &partitioner, "", (dir / "split").string());
  comm.barrier();  // the checkpoint is on disk
  const Finished split = run(c, &partitioner, (dir / "split" / checkpoint).string());
  CHECK(split.summary["status"] == "completed");
  if (comm.rank() == 0) {
    run(c, nullptr, "", (dir / "serial").string());
    const Finished serial = run(c, nullptr, (dir / "serial" / checkpoint).string());
    CHECK(serial.summary["status"] == "completed");
    CHECK(split.summary["steps"] == serial.summary["steps"]);
    CHECK(split.summary["rhs_evals"] == serial.summary["rhs_evals"]);
    INFO(comm.size() << " ranks");
    INFO("largest relative difference from the serial state: " << relative_difference(split.y, serial.y, serial.summary));
    CHECK(same_bits(split.y, serial.y));
  }
  comm.barrier();
  if (comm.rank() == 0) fs::remove_all(dir);
}

TEST_CASE("distributed run: an ARKODE checkpoint written over ranks continues over ranks as the serial one does serially",
          "[parallel][run][sundials][restart]") {
  check_restart_same_as_serial(dam_break("arkode_erk", {"output.checkpoint_every=0.02"}), "sundials", "checkpoint-0.02");
}

TEST_CASE("distributed run: a leapfrog_imex checkpoint written over ranks continues over ranks as the serial one does serially",
          "[parallel][run][imex][restart]") {
  // Its previous velocities (the predictor's) travel through the checkpoint, gathered and split again.
  check_restart_same_as_serial(channel("poiseuille.yaml", "leapfrog_imex", {"time.t_end=0.1", "output.times=[0.05,0.1]",
                                                                           "output.checkpoint_every=0.05"}),
                               "imex", "checkpoint-0.05");
}
