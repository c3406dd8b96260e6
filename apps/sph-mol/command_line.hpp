#pragma once
// The command line of the run command (`sph-mol --config FILE ...` / `sph-mol --restart DIR ...`):
// its options, the checks after parsing and the resolved config, apart from running the case, so
// the CLI fuzz target (fuzz/cli_fuzz.cpp) goes through exactly the code main.cpp uses.
#include <CLI/CLI.hpp>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol::app {

struct RunCommand {
  std::string config_path, output, restart;
  std::vector<std::string> overrides;
  int threads = 1;
  bool quiet = false;
  bool force_physics_change = false;
  bool overwrite = false;
  // Under mpirun (an MPI build, several ranks): the load imbalance past which the particles are
  // partitioned again (docs/parallel.md).
  double rebalance_threshold = 1.2;
};

// What is wrong with an --output given on the command line ("empty folder name", or that it is a
// symbolic link, io/links.hpp), or nullopt. Shared by the run command and the study subcommands, so
// both refuse the same names before any work; the output folder checks the link again when claimed.
std::optional<std::string> output_option_problem(const std::string& output);

// Declares the run command's options on the top-level app.
void add_run_options(CLI::App& app, RunCommand& cmd);

// Parses argv. Returns the exit code if the program ends here (0 after --help/--version, 2 for a bad
// command line, with the message on `out`/`err`), or nullopt to go on.
std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv, std::ostream& out,
                                      std::ostream& err);

// The config of the run command: --config FILE or DIR/config.yaml of --restart, with --set applied;
// notices go to `err`. On bad input (exit code 2) the message goes to `err` and nullopt is returned.
std::optional<Config> resolve_run_config(const CLI::App& app, const RunCommand& cmd, std::ostream& err);

}  // namespace sphmol::app
