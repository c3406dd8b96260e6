// sph-mol command line. `sph-mol --config FILE [--output DIR] [--set key.path=value]...` runs a case;
// subcommands (kernels, ...) register themselves through subcommand.hpp.
#include <CLI/CLI.hpp>

#include <iostream>

#include "sphmol/config/config.hpp"
#include "sphmol/core/version.hpp"
#include "sphmol/run/run_case.hpp"
#include "subcommand.hpp"

namespace {

int run(const std::string& config_path, const std::string& output, const std::vector<std::string>& overrides) {
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
    opt.log = &std::cerr;
    const auto s = sphmol::run_case(config, opt);
    const std::string dir = output.empty() ? config.output.directory : output;
    std::cout << "case " << s["case"].get<std::string>() << ": " << s["particles"]["fluid"] << " fluid + "
              << s["particles"]["wall"] << " wall particles, integrator " << s["integrator"]["name"].get<std::string>()
              << "\n  steps " << s["steps"] << ", rejected " << s["rejected_steps"] << ", RHS evaluations "
              << s["rhs_evals"] << ", neighbour rebuilds " << s["neighbor_rebuilds"] << ", wall time "
              << s["wall_seconds"].get<double>() << " s\n  final errors " << s["final_errors"].dump()
              << "\n  results in " << dir << "/summary.json\n";
    if (s["status"] == "blown_up") {
      std::cerr << "sph-mol: run " << s["blow_up"]["message"].get<std::string>() << "; last good state (t = "
                << s["blow_up"]["last_good_t"].get<double>() << " s) in " << dir << "/last_good_state.csv\n";
      return 3;  // distinct from config errors (2) and failures (1)
    }
  } catch (const std::exception& e) {
    std::cerr << "sph-mol: run failed: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sph-mol: smoothed particle hydrodynamics as a method of lines"};
  app.set_version_flag("--version", sphmol::version());
  app.require_subcommand(0, 1);
  std::string config_path, output;
  std::vector<std::string> overrides;
  app.add_option("--config", config_path, "case configuration (YAML), see config/README.md")->check(CLI::ExistingFile);
  app.add_option("--output", output, "output directory (overrides output.directory)");
  app.add_option("--set", overrides, "override a config value: key.path=value (repeatable)")->take_all()->expected(1);
  for (auto& s : sphmol::app::subcommands()) {
    auto* sub = app.add_subcommand(s.name, s.description);
    s.setup(*sub);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  for (auto& s : sphmol::app::subcommands())
    if (app.got_subcommand(s.name)) return s.run();
  if (config_path.empty()) {
    std::cerr << app.help() << "\nsph-mol: --config FILE is required to run a case\n";
    return 2;
  }
  return run(config_path, output, overrides);
}
