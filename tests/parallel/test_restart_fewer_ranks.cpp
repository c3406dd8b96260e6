// A checkpoint written over all ranks continues on fewer (run/checkpoint.hpp through run_case, over
// parallel/mpi_run.hpp): half of the ranks (4 -> 2, 3 -> 1, 2 -> 1) read it on a sub-communicator
// split off MPI_COMM_WORLD while the others wait, and end where the same checkpoint continued
// serially ends, bit for bit; with a leapfrog that is also where the uninterrupted run ends (ARKODE
// starts its error controller afresh from a checkpoint, so its continued steps are its own). The
// checkpoint holds the whole state in the serial layout, so the continuing ranks partition it
// afresh; the sub-communicator also shows that nothing in a run reaches for MPI_COMM_WORLD. Fluid
// that had left the domain before the checkpoint stays out on the continuing ranks, and the summary's
// "outflow" object is the serial continuation's (run/outflow.hpp).
#include <catch2/catch.hpp>
#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/mpi_run.hpp"
#include "sphmol/run/run_case.hpp"
#include "serial_reference.hpp"
#include "shot_scene.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
using namespace sphmol::parallel::testing;
namespace fs = std::filesystem;

namespace {

// MPI_Comm_split's communicator, freed with the object.
class SubCommunicator {
 public:
  SubCommunicator(MPI_Comm parent, bool member, int key) {
    MPI_Comm_split(parent, member ? 0 : MPI_UNDEFINED, key, &comm_);
  }
  ~SubCommunicator() {
    if (comm_ != MPI_COMM_NULL) MPI_Comm_free(&comm_);
  }
  SubCommunicator(const SubCommunicator&) = delete;
  SubCommunicator& operator=(const SubCommunicator&) = delete;
  bool member() const { return comm_ != MPI_COMM_NULL; }
  MPI_Comm handle() const { return comm_; }

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
};

// c runs uninterrupted over every rank, writing the checkpoint `checkpoint` (its folder name); the
// first half of the ranks then continue it and must end in the steps and the state of the serial
// continuation (`like_uninterrupted`: and of the uninterrupted run).
void check_continued_on_fewer_ranks(const Config& c, const std::string& name, const std::string& checkpoint, double rebalance,
                                    bool like_uninterrupted) {
  const Communicator world;
  const int fewer = std::max(1, world.size() / 2);
  const long pid = world.all_gather(static_cast<long>(::getpid()))[0];
  const fs::path dir = fs::temp_directory_path() /
                       ("sphmol-" + name + "-fewer-" + std::to_string(pid) + "-" + std::to_string(world.size()));
  const MpiRunPartitioner all(world, MpiRunPartitioner::default_tolerance, rebalance);
  const Finished whole = run(c, &all, "", (dir / "all").string());
  REQUIRE(whole.summary["status"] == "completed");
  world.barrier();  // the checkpoint is on disk

  const SubCommunicator sub(world.handle(), world.rank() < fewer, world.rank());
  if (sub.member()) {
    const Communicator comm(sub.handle());
    REQUIRE(comm.size() == fewer);
    const MpiRunPartitioner part(comm, MpiRunPartitioner::default_tolerance, rebalance);
    const Finished continued = run(c, &part, (dir / "all" / checkpoint).string());
    if (comm.rank() == 0) {
      const Finished serial = run(c, nullptr, (dir / "all" / checkpoint).string());
      INFO("written on " << world.size() << " ranks, continued on " << comm.size());
      CHECK(continued.summary["status"] == "completed");
      CHECK(continued.summary["parallel"]["ranks"] == fewer);
      CHECK(continued.summary["steps"] == serial.summary["steps"]);
      CHECK(same_bits(continued.y, serial.y));
      CHECK(continued.summary["outflow"] == serial.summary["outflow"]);
      if (like_uninterrupted) {
        CHECK(same_bits(continued.y, whole.y));
        // The case's series and monitors (Case::save_state) continue through the checkpoint too.
        CHECK(continued.summary["errors"] == whole.summary["errors"]);
        CHECK(continued.summary["final_errors"] == whole.summary["final_errors"]);
      }
    }
  }
  world.barrier();
  if (world.rank() == 0) fs::remove_all(dir);
}

}  // namespace

TEST_CASE("distributed run: a dam-break checkpoint written on every rank continues on half of them", "[parallel][run][restart]") {
  // The leapfrog's f and c travel in the checkpoint; partitioned again at every re-plan, so the
  // particles also migrate in both runs.
  const Config c = load_config(verification("dam_break.yaml"),
                               {"discretization.spacing=0.04", "time.t_end=0.08", "output.times=[0.04,0.08]",
                                "output.plots=false", "output.checkpoint_every=0.04"});
  check_continued_on_fewer_ranks(c, "dam-break", "checkpoint-0.04", 1.0, true);
}

TEST_CASE("distributed run: a 3D tank checkpoint written on every rank continues on half of them", "[parallel][run][restart]") {
  const Config c = load_config(verification("hydrostatic_3d.yaml"),
                               {"discretization.particles_across=8", "time.t_end=0.02", "output.times=[0.01,0.02]",
                                "output.plots=false", "output.checkpoint_every=0.01"});
  check_continued_on_fewer_ranks(c, "tank-3d", "checkpoint-0.01", 1.2, true);
}

TEST_CASE("distributed run: an ARKODE checkpoint written on every rank continues on half of them", "[parallel][run][restart][sundials]") {
  const Config c = load_config(verification("poiseuille.yaml"),
                               {"discretization.particles_across=20", "time.integrator=arkode_erk", "time.t_end=0.03",
                                "output.times=[0.015,0.03]", "output.plots=false", "output.checkpoint_every=0.015"});
  check_continued_on_fewer_ranks(c, "arkode", "checkpoint-0.015", 1.2, false);
}

TEST_CASE("distributed run: a checkpoint with fluid out, written on every rank, continues on half of them across more exits",
          "[parallel][run][restart][outflow]") {
  // The shot particle has left before the checkpoint (t = 0.09): the continuing ranks take it out
  // again at their start, from where it sits (run/outflow.hpp); the falling block then leaves
  // through the open floor after it. Partitioned again at every re-plan.
  const Config c = sphmol::testing::shot_scene({"fluid.body_force=[0.0, -9.81]", "health.max_outflow_fraction=1", "time.t_end=0.18",
                                                "output.times=[0.09, 0.18]", "output.checkpoint_every=0.09"});
  check_continued_on_fewer_ranks(c, "outflow", "checkpoint-0.09", 1.0, true);
}
