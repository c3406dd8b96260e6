#include "command_line.hpp"
#include "number_checks.hpp"

#include <filesystem>
#include <string>

#include "sphmol/io/links.hpp"
#include "sphmol/run/openmp_wait_policy.hpp"

namespace sphmol::app {

std::optional<std::string> output_option_problem(const std::string& output) {
  // An empty name would write into the current directory's root files.
  if (output.empty()) return "empty folder name";
  return final_link_message(output);
}

void add_run_options(CLI::App& app, RunCommand& cmd) {
  app.add_option("--restart", cmd.restart,
                 "continue from a checkpoint directory DIR/checkpoint-<t> (its config.yaml; --set still applies)");
  app.add_flag("--force-physics-change", cmd.force_physics_change,
               "with --restart: continue even if --set or an edited config.yaml changes the physics of the checkpoint");
  app.add_flag("--overwrite", cmd.overwrite,
               "the output directory may hold another run's results: delete the files that run listed first");
  app.add_flag("--quiet,-q", cmd.quiet, "no progress line and no per-output log lines on stderr");
  app.add_option("--config", cmd.config_path, "case configuration (YAML), see config/README.md")->check(CLI::ExistingFile);
  app.add_option("--output", cmd.output, "output directory (overrides output.directory)");
  app.add_option("--threads", cmd.threads, std::string("OpenMP threads for the RHS and vector operations (0 = all cores); idle threads spin ") +
                     bounded_spin_count +
                     " iterations at a barrier, then sleep, unless OMP_WAIT_POLICY or GOMP_SPINCOUNT is set "
                     "(docs/performance.md)")
      ->check(sphmol::app::non_negative_number());
  app.add_option("--set", cmd.overrides, "override a config value: key.path=value (repeatable)")->take_all()->expected(1);
#ifdef SPHMOL_HAVE_MPI
  app.add_option("--rebalance-threshold", cmd.rebalance_threshold,
                 "under mpirun: partition the particles again when the largest rank's pair work exceeds this many "
                 "times the mean (checked at each halo re-plan; default 1.2)")
      ->check(sphmol::app::number_above(1.0, false));
#endif
}

std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv, std::ostream& out,
                                      std::ostream& err) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e, out, err);  // prints the message (or --help / --version)
    return code == 0 ? 0 : 2;                // a bad command line is bad input, like a bad config
  }
  // Options of the run command given before a subcommand's name would be ignored by it: refuse them
  // (--threads applies to every command).
  for (const CLI::App* sub : app.get_subcommands()) {
    for (const CLI::Option* o : app.get_options()) {
      if (o->count() == 0 || o->get_name() == "--threads") continue;
      err << "sph-mol: " << o->get_name() << " is an option of the run command, not of `" << sub->get_name()
          << "`; give the options of `" << sub->get_name() << "` after its name (sph-mol " << sub->get_name()
          << " --help)\n";
      return 2;
    }
  }
  return std::nullopt;
}

std::optional<Config> resolve_run_config(const CLI::App& app, const RunCommand& cmd, std::ostream& err) {
  std::string path = cmd.config_path;
  // Given, even empty: an empty --output is not "no --output" (the config's folder would be used).
  if (app.get_option("--output")->count() > 0)
    if (const auto problem = output_option_problem(cmd.output)) {
      err << "sph-mol: --output: " << *problem << '\n';
      return std::nullopt;
    }
  if (cmd.force_physics_change && cmd.restart.empty()) {
    err << "sph-mol: --force-physics-change only applies to --restart\n";
    return std::nullopt;
  }
  if (!cmd.restart.empty()) {
    if (!cmd.config_path.empty()) {
      err << "sph-mol: --restart takes the config from the checkpoint; do not give --config too "
             "(change values with --set)\n";
      return std::nullopt;
    }
    if (const auto link = final_link_message(cmd.restart)) {
      err << "sph-mol: restart error: --restart " << *link << '\n';
      return std::nullopt;
    }
    path = (std::filesystem::path(cmd.restart) / "config.yaml").string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
      err << "sph-mol: restart error: " << path << " not found (--restart expects a DIR/checkpoint-<t> "
          << "directory written by output.checkpoint_every or an interrupted run)\n";
      return std::nullopt;
    }
  } else if (path.empty()) {
    err << app.help() << "\nsph-mol: --config FILE is required to run a case\n";
    return std::nullopt;
  }
  try {
    Config config = load_config(path, cmd.overrides);
    for (const auto& notice : config.notices) err << "sph-mol: " << notice << '\n';
    return config;
  } catch (const ConfigError& e) {
    err << "sph-mol: config error: " << e.what() << '\n';
    return std::nullopt;
  }
}

}  // namespace sphmol::app
