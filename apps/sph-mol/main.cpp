// sph-mol command line. `sph-mol --config FILE [--output DIR] [--set key.path=value]...` runs a case;
// subcommands (kernels, ...) register themselves through subcommand.hpp.
#include <CLI/CLI.hpp>

#include <omp.h>

#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <iostream>

#include "sphmol/config/config.hpp"
#include "sphmol/core/version.hpp"
#include "sphmol/run/checkpoint.hpp"
#include "sphmol/run/run_case.hpp"
#include "subcommand.hpp"

namespace {

// Exit codes: 0 done, 1 run failed, 2 bad input (config, command line, checkpoint; nothing is
// written), 3 blown up (last good state written), 128 + signal when interrupted (130 SIGINT, 143 SIGTERM; checkpoint + summary written).
int run(const std::string& config_path, const std::string& output, const std::vector<std::string>& overrides,
        const std::string& restart = {}, bool quiet = false) {
  sphmol::Config config;
  try {
    config = sphmol::load_config(config_path, overrides);
  } catch (const sphmol::ConfigError& e) {
    std::cerr << "sph-mol: config error: " << e.what() << '\n';
    return 2;
  }
  for (const auto& notice : config.notices) std::cerr << "sph-mol: " << notice << '\n';
  try {
    sphmol::RunOptions opt;
    opt.output_dir = output;
    opt.log = quiet ? nullptr : &std::cerr;
    if (!quiet && ::isatty(STDERR_FILENO)) opt.progress = &std::cerr;
    opt.restart_from = restart;
    opt.handle_signals = true;
    const auto s = sphmol::run_case(config, opt);
    if (s.contains("warnings"))
      for (const auto& w : s["warnings"]) std::cerr << "sph-mol: warning: " << w.get<std::string>() << '\n';
    if (const int code = sphmol::interrupted_exit_code(s)) {
      std::cerr << "sph-mol: interrupted at t = " << s["t_reached"].get<double>() << " s; summary and checkpoint in "
                << (output.empty() ? config.output.directory : output) << "\n";
      return code;
    }
    const std::string dir = output.empty() ? config.output.directory : output;
    if (s["status"] == "blown_up") {
      std::cerr << "sph-mol: run " << s["blow_up"]["message"].get<std::string>() << "; last good state (t = "
                << s["blow_up"]["last_good_t"].get<double>() << " s) in " << dir << "/last_good_state.csv\n";
      return 3;  // distinct from config errors (2) and failures (1)
    }
    std::cout << "case " << s["case"].get<std::string>() << ": " << s["particles"]["fluid"] << " fluid + "
              << s["particles"]["wall"] << " wall particles, integrator " << s["integrator"]["name"].get<std::string>()
              << "\n  steps " << s["steps"] << ", rejected " << s["rejected_steps"] << ", RHS evaluations "
              << s["rhs_evals"] << ", neighbour rebuilds " << s["neighbor_rebuilds"] << ", wall time "
              << s["wall_seconds"].get<double>() << " s\n  final errors " << s["final_errors"].dump()
              << "\n  results in " << dir << "/summary.json\n";
  } catch (const sphmol::CheckpointError& e) {
    std::cerr << "sph-mol: restart error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "sph-mol: run failed: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // Past `ulimit -f` a write fails with EFBIG and the writer reports it; the default action would kill
  // the run with no message and no summary.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"sph-mol: smoothed particle hydrodynamics as a method of lines"};
  app.set_version_flag("--version", sphmol::version());
  app.require_subcommand(0, 1);
  std::string config_path, output;
  std::vector<std::string> overrides;
  int threads = 1;
  std::string restart;
  bool quiet = false;
  app.add_option("--restart", restart,
                 "continue from a checkpoint directory DIR/checkpoint-<t> (its config.yaml; --set still applies)");
  app.add_flag("--quiet,-q", quiet, "no progress line and no per-output log lines on stderr");
  app.add_option("--config", config_path, "case configuration (YAML), see config/README.md")->check(CLI::ExistingFile);
  app.add_option("--output", output, "output directory (overrides output.directory)");
  app.add_option("--threads", threads, "OpenMP threads for the RHS and vector operations (0 = all cores)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--set", overrides, "override a config value: key.path=value (repeatable)")->take_all()->expected(1);
  for (auto& s : sphmol::app::subcommands()) {
    auto* sub = app.add_subcommand(s.name, s.description);
    s.setup(*sub);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints the message (or --help / --version)
    return code == 0 ? 0 : 2;      // a bad command line is bad input, like a bad config
  }
  if (threads > omp_get_num_procs())  // oversubscribed threads only wait for each other
    std::cerr << "sph-mol: warning: --threads " << threads << " is more than the " << omp_get_num_procs()
              << " cores of this machine\n";
  if (threads > 0) omp_set_num_threads(threads);
  for (auto& s : sphmol::app::subcommands())
    if (app.got_subcommand(s.name)) return s.run();
  if (!restart.empty()) {
    if (!config_path.empty()) {
      std::cerr << "sph-mol: --restart takes the config from the checkpoint; do not give --config too "
                   "(change values with --set)\n";
      return 2;
    }
    const std::string cfg = (std::filesystem::path(restart) / "config.yaml").string();
    if (!std::filesystem::is_regular_file(cfg)) {
      std::cerr << "sph-mol: restart error: " << cfg << " not found (--restart expects a DIR/checkpoint-<t> "
                << "directory written by output.checkpoint_every or an interrupted run)\n";
      return 2;
    }
    return run(cfg, output, overrides, restart, quiet);
  }
  if (config_path.empty()) {
    std::cerr << app.help() << "\nsph-mol: --config FILE is required to run a case\n";
    return 2;
  }
  return run(config_path, output, overrides, {}, quiet);
}
