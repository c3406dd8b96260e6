// sph-mol compare --config FILE --integrators LIST [--output DIR] [--reference-dt DT] [--rtols LIST]
//                  [--step-factors LIST] [--targets LIST] [--set k=v]...
// Integrator comparison: see lib/sphmol/studies/compare.hpp for the sweeps.
#include <iostream>

#include "sphmol/studies/compare.hpp"
#include "number_checks.hpp"
#include "sphmol/run/output_folder.hpp"
#include "study_common.hpp"
#include "subcommand.hpp"

namespace {

struct {
  std::string config, integrators, output = "out/compare";
  std::vector<std::string> overrides;
  double reference_dt = 0.0;
  std::vector<double> rtols, step_factors, targets;
} opt;

int run() {
  if (!sphmol::app::output_option_ok("compare", opt.output)) return 2;
  auto config = sphmol::app::load_study_config(opt.config, opt.overrides, "compare");
  if (!config) return 2;
  const auto integrators = sphmol::app::parse_integrators_option("compare", opt.integrators, config->time.table);
  if (!integrators) return 2;
  // A sweep that no listed integrator uses would be silently ignored.
  bool any_adaptive = false, any_fixed = false;
  for (const auto& s : *integrators) (s.adaptive() ? any_adaptive : any_fixed) = true;
  if (!opt.rtols.empty() && !any_adaptive)
    return sphmol::app::bad_option("compare", "--rtols", "no integrator in --integrators has a tolerance (arkode_erk, arkode_imex, cvode_adams do)");
  if (!opt.step_factors.empty() && !any_fixed)
    return sphmol::app::bad_option("compare", "--step-factors", "no integrator in --integrators takes a fixed or CFL step (leapfrog, leapfrog_kdk, leapfrog_imex do)");
  if (!sphmol::app::coarse_to_fine_ok("compare", "--rtols", opt.rtols) ||
      !sphmol::app::coarse_to_fine_ok("compare", "--step-factors", opt.step_factors) ||
      !sphmol::app::distinct_ok("compare", "--targets", opt.targets))
    return 2;
  try {
    sphmol::CompareOptions o;
    o.integrators = *integrators;
    o.output_dir = opt.output;
    o.log = &std::cerr;
    if (opt.reference_dt > 0.0) o.reference_dt = opt.reference_dt;
    if (!opt.rtols.empty()) o.rtols = opt.rtols;
    if (!opt.step_factors.empty()) o.step_factors = opt.step_factors;
    if (!opt.targets.empty()) o.targets = opt.targets;
    const auto j = sphmol::run_compare(*config, o);
    for (const auto& f : j["fastest"]) {
      std::cout << "compare: fastest at " << f["error"].get<std::string>() << " = " << f["target_error"].get<double>() << ": ";
      const auto& b = f["fastest"];
      if (b.is_null()) std::cout << "no integrator reached it\n";
      else
        std::cout << b["integrator"].get<std::string>() << " ("
                  << (b["upper_bound"].get<bool>() ? "its cheapest run, " + b["first_setting_at_target"].get<std::string>() +
                                                         ", is already below: "
                                                   : "interpolated: ")
                  << b["wall_seconds"].get<double>() << " s wall)";
      const auto& c = f["fastest_cpu"];
      if (!c.is_null()) std::cout << "; by CPU time: " << c["integrator"].get<std::string>() << " (" << c["cpu_seconds"].get<double>() << " s)";
      std::cout << '\n';
    }
    std::cout << "compare: results in " << opt.output << "/comparison.csv, comparison.json, comparison.png\n";
  } catch (const sphmol::OutputFolderError& e) {
    std::cerr << "sph-mol compare: " << e.what() << '\n';
    return 2;  // the folder is in use: bad input, nothing written
  } catch (const std::invalid_argument& e) {
    std::cerr << "sph-mol compare: " << e.what() << '\n';
    return 2;  // a study the options cannot make (a reference step longer than the run): bad input
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
                     "comma-separated: leapfrog, leapfrog_kdk, leapfrog_imex, arkode_erk, arkode_erk:TABLE, cvode_adams, arkode_imex, arkode_imex:TABLE")
          ->required();
      sub.add_option("--output", opt.output, "output directory (default out/compare)");
      sub.add_option("--reference-dt", opt.reference_dt,
                     "error = time error against an ARKODE Verner 8(5)6 run at this fixed step (default: the case's exact error)")
          ->check(sphmol::app::positive_number());
      sub.add_option("--rtols", opt.rtols, "tolerance sweep of the adaptive integrators, coarse to fine (default 1e-3,...,1e-7)")
          ->delimiter(',')
          ->check(sphmol::app::positive_number());
      sub.add_option("--step-factors", opt.step_factors,
                     "factors on time.dt or the CFL coefficients for the leapfrogs, coarse to fine (default 1,0.5,0.25,0.125)")
          ->delimiter(',')
          ->check(sphmol::app::positive_number());
      sub.add_option("--targets", opt.targets, "target errors for the fastest-integrator summary (default 0.01,0.001)")
          ->delimiter(',')
          ->check(sphmol::app::positive_number());
      sub.add_option("--set", opt.overrides, "override a config value: key.path=value (repeatable)")->take_all()->expected(1);
    },
    run}};

}  // namespace
