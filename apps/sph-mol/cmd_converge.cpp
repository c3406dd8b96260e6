// sph-mol converge --config FILE --refine time|space [--levels N] [--integrators LIST] [--dt0 DT]
// Convergence study: see lib/sphmol/studies/converge.hpp.
#include <cmath>
#include <iostream>

#include "sphmol/studies/converge.hpp"
#include "number_checks.hpp"
#include "sphmol/run/output_folder.hpp"
#include "study_common.hpp"
#include "subcommand.hpp"

namespace {

struct {
  std::string config, refine, integrators, output = "out/converge";
  int levels = 4;
  double dt0 = 0.0;
  std::vector<std::string> overrides;
} opt;

int run() {
  if (!sphmol::app::output_option_ok("converge", opt.output)) return 2;
  if (opt.dt0 > 0.0 && opt.refine != "time") return sphmol::app::bad_option("converge", "--dt0", "only with --refine time");
  auto config = sphmol::app::load_study_config(opt.config, opt.overrides, "converge");
  if (!config) return 2;
  try {
    sphmol::ConvergeOptions o;
    o.refine = opt.refine;
    o.levels = opt.levels;
    if (!opt.integrators.empty()) {
      const auto integrators = sphmol::app::parse_integrators_option("converge", opt.integrators, config->time.table);
      if (!integrators) return 2;
      o.integrators = *integrators;
      for (const auto& s : o.integrators)
        if (opt.refine == "time" && s.integrator == "cvode_adams")
          return sphmol::app::bad_option("converge", "--integrators", "cvode_adams has no fixed step (--refine time needs one)");
    }
    if (opt.dt0 > 0) o.dt0 = opt.dt0;
    o.output_dir = opt.output;
    o.log = &std::cerr;
    const auto j = sphmol::run_converge(*config, o);
    for (const auto& s : j["series"]) {
      std::cout << s["integrator"].get<std::string>() << ": observed order ";
      if (s["observed_order"].is_null()) std::cout << "not measured (no two consecutive clean levels)";
      else
        std::cout << s["observed_order"].get<double>() << " (levels " << s["order_levels"][0] << "-" << s["order_levels"][1] << ")";
      if (!s["expected_order"].is_null()) std::cout << " (expected " << s["expected_order"] << ")";
      std::cout << ", errors " << s["errors"].dump() << '\n';
    }
    std::cout << "converge: results in " << opt.output << "/convergence.csv, convergence.json, convergence.png\n";
  } catch (const sphmol::OutputFolderError& e) {
    std::cerr << "sph-mol converge: " << e.what() << '\n';
    return 2;  // the folder is in use: bad input, nothing written
  } catch (const std::invalid_argument& e) {
    std::cerr << "sph-mol converge: " << e.what() << '\n';
    return 2;  // a study the options cannot make (a step longer than the run, ...): bad input
  } catch (const std::exception& e) {
    std::cerr << "sph-mol converge: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

const sphmol::app::RegisterSubcommand reg{sphmol::app::Subcommand{
    "converge", "Convergence study: fixed step halved per level (time) or particle spacing halved (space)",
    [](CLI::App& sub) {
      sub.add_option("--config", opt.config, "case configuration (YAML)")->required()->check(CLI::ExistingFile);
      sub.add_option("--refine", opt.refine, "time or space")->required()->check(CLI::IsMember({"time", "space"}));
      sub.add_option("--levels", opt.levels, "number of levels (default 4)")->check(CLI::Range(2, 8));
      sub.add_option("--integrators", opt.integrators,
                     "comma-separated (default for time: leapfrog, leapfrog_kdk and ERK tables of orders 2, 3, 4)");
      sub.add_option("--dt0", opt.dt0,
                     "coarsest fixed step for --refine time (default: time.dt of the config, else the case's CFL step at t = 0 shortened to divide time.t_end)")
          ->check(sphmol::app::positive_number());
      sub.add_option("--output", opt.output, "output directory (default out/converge)");
      sub.add_option("--set", opt.overrides, "override a config value: key.path=value (repeatable)")->take_all()->expected(1);
    },
    run}};

}  // namespace
