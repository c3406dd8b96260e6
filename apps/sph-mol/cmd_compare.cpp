// sph-mol compare --config FILE --integrators LIST [--output DIR] [--set k=v]...
// Integrator comparison: see lib/sphmol/studies/compare.hpp for the sweeps.
#include <iostream>

#include "sphmol/studies/compare.hpp"
#include "study_common.hpp"
#include "subcommand.hpp"

namespace {

struct {
  std::string config, integrators, output = "out/compare";
  std::vector<std::string> overrides;
} opt;

int run() {
  auto config = sphmol::app::load_study_config(opt.config, opt.overrides, "compare");
  if (!config) return 2;
  try {
    sphmol::CompareOptions o;
    o.integrators = sphmol::parse_integrator_list(opt.integrators, config->time.table);
    o.output_dir = opt.output;
    o.log = &std::cerr;
    sphmol::run_compare(*config, o);
    std::cout << "compare: results in " << opt.output << "/comparison.csv, comparison.json, comparison.png\n";
  } catch (const std::exception& e) {
    std::cerr << "sph-mol compare: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

const sphmol::app::RegisterSubcommand reg{sphmol::app::Subcommand{
    "compare", "Run a case with several integrators over an accuracy sweep: error vs wall time (CSV, JSON, PNG)",
    [](CLI::App& sub) {
      sub.add_option("--config", opt.config, "case configuration (YAML)")->required()->check(CLI::ExistingFile);
      sub.add_option("--integrators", opt.integrators,
                     "comma-separated: leapfrog, leapfrog_kdk, arkode_erk, arkode_erk:TABLE, cvode_adams")
          ->required();
      sub.add_option("--output", opt.output, "output directory (default out/compare)");
      sub.add_option("--set", opt.overrides, "override a config value: key.path=value (repeatable)")->take_all()->expected(1);
    },
    run}};

}  // namespace
