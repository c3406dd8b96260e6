// sph-mol command line. `sph-mol --config FILE [--output DIR] [--set key.path=value]...` runs a case
// (options: command_line.hpp); subcommands (kernels, ...) register themselves through subcommand.hpp.
#include <CLI/CLI.hpp>

#include <omp.h>

#include <unistd.h>

#include <csignal>
#include <iostream>
#include <new>
#include <optional>
#include <sstream>

#include "sphmol/config/config.hpp"
#include "sphmol/config/scene_checks.hpp"
#include "sphmol/core/version.hpp"
#include "sphmol/run/checkpoint.hpp"
#include "sphmol/run/openmp_wait_policy.hpp"
#include "sphmol/run/output_folder.hpp"
#include "sphmol/run/partitioned_run.hpp"
#include "sphmol/run/run_case.hpp"
#include "command_line.hpp"
#include "subcommand.hpp"

#ifdef SPHMOL_HAVE_MPI
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/mpi_environment.hpp"
#include "sphmol/parallel/mpi_run.hpp"
#endif

namespace {

// Exit codes: 0 done, 1 run failed, 2 bad input (config, command line, checkpoint; nothing is
// written), 3 blown up (last good state written), 128 + signal when interrupted (130 SIGINT, 143 SIGTERM; checkpoint + summary written).
// `partitioner`: the run is split over MPI ranks (docs/parallel.md); rank 0 prints and writes. An
// error that may concern one rank only ends every rank (MPI_Abort), so none waits for it forever;
// a config error is the same on every rank, which all return 2.
int run(const sphmol::Config& config, const sphmol::app::RunCommand& cmd, const sphmol::RunPartitioner* partitioner) {
  const std::string& output = cmd.output;
  const bool root = !partitioner || partitioner->root();
  const auto fail = [partitioner](int code) {
#ifdef SPHMOL_HAVE_MPI
    if (partitioner) MPI_Abort(MPI_COMM_WORLD, code);
#endif
    return code;
  };
  try {
    sphmol::RunOptions opt;
    opt.output_dir = output;
    opt.log = cmd.quiet || !root ? nullptr : &std::cerr;
    if (!cmd.quiet && root && ::isatty(STDERR_FILENO)) opt.progress = &std::cerr;
    opt.restart_from = cmd.restart;
    opt.force_physics_change = cmd.force_physics_change;
    opt.overwrite = cmd.overwrite;
    // Over ranks every rank handles them, and the ranks stop at the step where they agree
    // (docs/parallel.md: what mpirun does with a signal it receives).
    opt.handle_signals = true;
    opt.partitioner = partitioner;
    const auto s = sphmol::run_case(config, opt);
    if (!root) return s["status"] == "blown_up" ? 3 : sphmol::interrupted_exit_code(s);
    if (s.contains("warnings"))
      for (const auto& w : s["warnings"]) std::cerr << "sph-mol: warning: " << w.get<std::string>() << '\n';
    const std::string dir = s.value("output_directory", output.empty() ? config.output.directory : output);
    if (const int code = sphmol::interrupted_exit_code(s)) {
      std::cerr << "sph-mol: interrupted at t = " << s["t_reached"].get<double>() << " s; summary and checkpoint in "
                << dir << "\n";
      return code;
    }
    if (s["status"] == "blown_up") {
      const auto& b = s["blow_up"];
      std::cerr << "sph-mol: run " << b["message"].get<std::string>() << "; last good state (t = "
                << b["last_good_t"].get<double>() << " s)";
      // A run over ranks writes no state file (docs/parallel.md).
      if (b.contains("state_file")) std::cerr << " in " << dir << "/" << b["state_file"].get<std::string>();
      std::cerr << '\n';
      return 3;  // distinct from config errors (2) and failures (1)
    }
    std::cout << "case " << s["case"].get<std::string>() << ": " << s["particles"]["fluid"] << " fluid + "
              << s["particles"]["wall"] << " wall particles, integrator " << s["integrator"]["name"].get<std::string>()
              << "\n  steps " << s["steps"] << ", rejected " << s["rejected_steps"] << ", RHS evaluations "
              << s["rhs_evals"] << ", neighbour rebuilds " << s["neighbor_rebuilds"] << ", wall time "
              << s["wall_seconds"].get<double>() << " s\n  final errors " << s["final_errors"].dump()
              << "\n  results in " << dir << "/summary.json\n";
  } catch (const sphmol::ConfigError& e) {
    // Config checks that need the built scene (a probe outside it): bad input, before any file.
    if (root) std::cerr << "sph-mol: config error: " << e.what() << '\n';
    return 2;
  } catch (const sphmol::CheckpointError& e) {
    std::cerr << "sph-mol: restart error: " << e.what() << '\n';
    return fail(2);
  } catch (const sphmol::OutputFolderError& e) {
    std::cerr << "sph-mol: " << e.what() << '\n';
    return fail(2);
  } catch (const std::bad_alloc&) {
    std::cerr << "sph-mol: run failed: out of memory\n";
    return fail(1);
  } catch (const std::exception& e) {
    std::cerr << "sph-mol: run failed: " << e.what() << '\n';
    return fail(1);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // Past `ulimit -f` a write fails with EFBIG and the writer reports it; the default action would kill
  // the run with no message and no summary.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    CLI::App app{"sph-mol: smoothed particle hydrodynamics as a method of lines"};
    app.set_version_flag("--version", sphmol::version());
    app.require_subcommand(0, 1);
    sphmol::app::RunCommand cmd;
    sphmol::app::add_run_options(app, cmd);
    for (auto& s : sphmol::app::subcommands()) {
      auto* sub = app.add_subcommand(s.name, s.description);
      s.setup(*sub);
    }
    // Under mpirun every rank reads the same command line: rank 0 alone tells what is wrong with it
    // (MPI starts after it, so the launcher's environment says which rank this is).
#ifdef SPHMOL_HAVE_MPI
    const bool first_rank = sphmol::parallel::MpiEnvironment::launched_rank() == 0;
#else
    const bool first_rank = true;
#endif
    std::ostringstream not_shown;
    std::ostream& cli_out = first_rank ? std::cout : not_shown;
    std::ostream& cli_err = first_rank ? std::cerr : not_shown;
    if (const auto code = sphmol::app::parse_command_line(app, argc, argv, cli_out, cli_err)) return *code;
    // A short spin at barriers, so that a busy machine does not make two threads slower than one
    // (run/openmp_wait_policy.hpp). Before any parallel region, and before any message, which the
    // re-executed program would print again. Returns only if not re-executed.
    if (!sphmol::bound_openmp_spin(cmd.threads > 0 ? cmd.threads : omp_get_num_procs(), argv))
      cli_err << "sph-mol: warning: could not restart with GOMP_SPINCOUNT=" << sphmol::bounded_spin_count
                << "; idle threads spin at barriers for libgomp's default time (set OMP_WAIT_POLICY=passive or "
                   "GOMP_SPINCOUNT to choose)\n";
    if (cmd.threads > omp_get_num_procs())  // oversubscribed threads only wait for each other
      cli_err << "sph-mol: warning: --threads " << cmd.threads << " is more than the " << omp_get_num_procs()
                << " cores of this machine\n";
    if (cmd.threads > 0) omp_set_num_threads(cmd.threads);
#ifdef SPHMOL_HAVE_MPI
    // Started by mpirun with several ranks: the run is split over them. One rank runs serially,
    // and without mpirun MPI is not started at all.
    std::optional<sphmol::parallel::MpiEnvironment> mpi;
    if (sphmol::parallel::MpiEnvironment::launched()) mpi.emplace(argc, argv);
    std::optional<sphmol::parallel::Communicator> world;
    if (mpi) world.emplace();
    const int ranks = world ? world->size() : 1;
    const bool root = !world || world->rank() == 0;
#else
    const int ranks = 1;
    const bool root = true;
#endif
    for (auto& s : sphmol::app::subcommands())
      if (app.got_subcommand(s.name)) {
        if (ranks > 1) {  // each rank would run the whole study, into the same files
          if (root) std::cerr << "sph-mol: `" << s.name << "` does not run over several MPI ranks; run it without mpirun\n";
          return 2;
        }
        return s.run();
      }
#ifdef SPHMOL_HAVE_MPI
    // The config's memory check asks this machine for its ranks' shares of the scene.
    if (world) sphmol::set_ranks_on_machine({ranks, world->ranks_on_this_machine()});
    if (ranks == 1 && app.get_option("--rebalance-threshold")->count() > 0)
      std::cerr << "sph-mol: --rebalance-threshold has no effect: the run is not split over MPI ranks (start it with mpirun -n N, N > 1)\n";
#endif
    std::ostringstream elsewhere;  // every rank reads the config alike: rank 0 tells
    const auto config = sphmol::app::resolve_run_config(app, cmd, root ? static_cast<std::ostream&>(std::cerr) : elsewhere);
    if (!config) return 2;
#ifdef SPHMOL_HAVE_MPI
    std::optional<sphmol::parallel::MpiRunPartitioner> partitioner;
    if (ranks > 1) partitioner.emplace(*world, sphmol::parallel::MpiRunPartitioner::default_tolerance, cmd.rebalance_threshold);
    const int code = run(*config, cmd, partitioner ? &*partitioner : nullptr);
    // The ranks end together: mpirun ends the whole job as soon as one rank exits with a code other
    // than 0 (3, 130, 143), which must not cut rank 0's checkpoint or summary short.
    if (partitioner) world->barrier();
    return code;
#else
    return run(*config, cmd, nullptr);
#endif
  } catch (const std::bad_alloc&) {
    // Whatever asked for more memory than there is (input limits catch the usual causes first).
    std::cerr << "sph-mol: out of memory\n";
    return 1;
  }
}
