// SIGINT/SIGTERM in a run over ranks (run/signals.hpp, PartitionedRun::check): a signal that reaches
// one rank only stops every rank at the same step, the step after the one where it came (the ranks
// agree in the next step's health check); rank 0 writes the checkpoint of the whole state and the
// summary says "interrupted" with that signal on every rank. The checkpoint, continued serially,
// ends in the uninterrupted run's state bit for bit (leapfrog). The signal is raised with raise()
// from the run loop's after_step hook at a chosen time, so the step it comes at is deterministic.
#include <catch2/catch.hpp>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/mpi_run.hpp"
#include "sphmol/run/checkpoint.hpp"
#include "sphmol/run/run_case.hpp"
#include "serial_reference.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
using namespace sphmol::parallel::testing;
namespace fs = std::filesystem;

namespace {

struct Interrupted {
  nlohmann::json summary;
  long raised_at_step = 0;  // the signalled ranks' step count when they raised it (0 on the others)
  fs::path dir;
};

// c over every rank with the handlers installed; at the first step that reaches t_signal, each rank
// listed in `signals` raises its signal (in the order given).
Interrupted interrupted_run(const Config& c, const std::string& name, double t_signal,
                            const std::vector<std::pair<int, int>>& signals) {
  const Communicator comm;
  const long pid = comm.all_gather(static_cast<long>(::getpid()))[0];
  Interrupted r;
  r.dir = fs::temp_directory_path() / ("sphmol-" + name + "-" + std::to_string(pid) + "-" + std::to_string(comm.size()));
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, 1.2);
  RunOptions opt;
  opt.output_dir = r.dir.string();
  opt.partitioner = &partitioner;
  opt.handle_signals = true;
  long steps = 0;
  opt.after_step = [&](double t) {
    ++steps;
    if (r.raised_at_step || t < t_signal) return;
    for (const auto& [rank, sig] : signals)
      if (rank == comm.rank()) {
        r.raised_at_step = steps;
        std::raise(sig);
      }
  };
  r.summary = run_case(c, opt);
  return r;
}

// What every rank must agree on: the status, the signal, the time reached and the steps.
void check_same_on_every_rank(const nlohmann::json& s) {
  const Communicator comm;
  const auto signals = comm.all_gather(s.value("signal", 0));
  const auto steps = comm.all_gather(s["steps"].get<long>());
  const auto times = comm.all_gather(s.value("t_reached", -1.0));
  for (int r = 0; r < comm.size(); ++r) {
    INFO("rank " << r << " of " << comm.size());
    CHECK(signals[r] == signals[0]);
    CHECK(steps[r] == steps[0]);
    CHECK(times[r] == times[0]);
  }
}

}  // namespace

TEST_CASE("distributed run: a signal on one rank stops every rank at the same step with a checkpoint that restarts exactly",
          "[parallel][run][signals]") {
  // The dam break: particles travel, so the halo is planned again during the run.
  const Config c = load_config(verification("dam_break.yaml"), {"discretization.spacing=0.04", "time.t_end=0.06",
                                                                "output.times=[0.03,0.06]", "output.plots=false"});
  const Communicator comm;
  const int last = comm.size() - 1;
  const Interrupted r = interrupted_run(c, "signal-one-rank", 0.035, {{last, SIGTERM}});
  const nlohmann::json& s = r.summary;
  REQUIRE(s["status"] == "interrupted");
  CHECK(s["signal"] == SIGTERM);
  CHECK(interrupted_exit_code(s) == 143);
  check_same_on_every_rank(s);
  // The step after the one at which the signal came.
  const long raised_at = comm.all_gather(r.raised_at_step)[static_cast<std::size_t>(last)];
  CHECK(raised_at > 0);
  CHECK(s["steps"].get<long>() == raised_at + 1);
  const double t = s["t_reached"].get<double>();
  CHECK(t > 0.035);
  CHECK(t < 0.06);
  if (comm.rank() == 0) {
    // The output time before the signal was measured, and the files say interrupted.
    CHECK(s["errors"].size() == 1);
    std::ifstream in(r.dir / "summary.json");
    CHECK(nlohmann::json::parse(in)["status"] == "interrupted");
    const fs::path checkpoint = r.dir / checkpoint_name(t);
    REQUIRE(fs::exists(checkpoint / "checkpoint.json"));
    // Continued serially: the uninterrupted run's state, bit for bit.
    const Finished continued = run(c, nullptr, checkpoint.string());
    const Finished& whole = serial_run(c);
    CHECK(continued.summary["status"] == "completed");
    CHECK(continued.summary["steps"] == whole.summary["steps"]);
    INFO("largest relative difference: " << relative_difference(continued.y, whole.y, whole.summary));
    CHECK(same_bits(continued.y, whole.y));
  }
  comm.barrier();
  if (comm.rank() == 0) fs::remove_all(r.dir);
}

TEST_CASE("distributed run: different signals at the same step end every rank with the largest", "[parallel][run][signals]") {
  // SIGINT on rank 0 and SIGTERM on the last rank (on one rank: both, SIGTERM last).
  const Config c = load_config(verification("poiseuille.yaml"), {"discretization.particles_across=20", "time.integrator=leapfrog",
                                                                 "time.t_end=0.02", "output.times=[0.02]", "output.plots=false"});
  const Communicator comm;
  const Interrupted r = interrupted_run(c, "signals-differ", 0.005, {{0, SIGINT}, {comm.size() - 1, SIGTERM}});
  CHECK(r.summary["status"] == "interrupted");
  CHECK(r.summary["signal"] == SIGTERM);
  check_same_on_every_rank(r.summary);
  comm.barrier();
  if (comm.rank() == 0) fs::remove_all(r.dir);
}
