// sph-mol stability --config FILE [--output DIR] [--sound-speed-factors LIST] [--step-factors LIST]
// Stability map: see lib/sphmol/studies/stability.hpp.
#include <iostream>

#include "sphmol/studies/stability.hpp"
#include "number_checks.hpp"
#include "sphmol/run/output_folder.hpp"
#include "study_common.hpp"
#include "subcommand.hpp"

namespace {

struct {
  std::string config, output = "out/stability";
  std::vector<double> c_factors, step_factors;
  double threshold = 0.002;
  int samples = 20;
  std::vector<std::string> overrides;
} opt;

int run() {
  if (!sphmol::app::output_option_ok("stability", opt.output)) return 2;
  if (!sphmol::app::distinct_ok("stability", "--sound-speed-factors", opt.c_factors) ||
      !sphmol::app::distinct_ok("stability", "--step-factors", opt.step_factors))
    return 2;
  auto config = sphmol::app::load_study_config(opt.config, opt.overrides, "stability");
  if (!config) return 2;
  try {
    sphmol::StabilityOptions o;
    if (!opt.c_factors.empty()) o.sound_speed_factors = opt.c_factors;
    if (!opt.step_factors.empty()) o.step_factors = opt.step_factors;
    o.osc_threshold = opt.threshold;
    o.samples = opt.samples;
    o.output_dir = opt.output;
    o.log = &std::cerr;
    sphmol::run_stability(*config, o);
    std::cout << "stability: results in " << opt.output << "/stability.csv, stability.json, stability.png\n";
  } catch (const sphmol::OutputFolderError& e) {
    std::cerr << "sph-mol stability: " << e.what() << '\n';
    return 2;  // the folder is in use: bad input, nothing written
  } catch (const sphmol::ConfigError& e) {
    std::cerr << "sph-mol stability: config error: " << e.what() << '\n';
    return 2;  // a factor the case refuses (scale_sound_speed), before anything is written
  } catch (const std::exception& e) {
    std::cerr << "sph-mol stability: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

const sphmol::app::RegisterSubcommand reg{sphmol::app::Subcommand{
    "stability", "Stability map over sound speed and step: stable / oscillating / blown up (CSV, JSON, PNG)",
    [](CLI::App& sub) {
      sub.add_option("--config", opt.config, "case configuration (YAML)")->required()->check(CLI::ExistingFile);
      sub.add_option("--output", opt.output, "output directory (default out/stability)");
      sub.add_option("--sound-speed-factors", opt.c_factors, "factors on fluid.eos.sound_speed (default 0.25,0.5,1,2)")
          ->delimiter(',')
          ->check(sphmol::app::positive_number());
      sub.add_option("--step-factors", opt.step_factors,
                     "factors on time.dt (fixed step) or on the time.cfl coefficients (default 0.5,1,2,4)")
          ->delimiter(',')
          ->check(sphmol::app::positive_number());
      sub.add_option("--osc-threshold", opt.threshold, "|e_signed - late mean| above which a swing counts, in units of v0 (default 0.002)")
          ->check(sphmol::app::non_negative_number());
      sub.add_option("--samples", opt.samples, "equally spaced sample times (default 20)")->check(CLI::Range(3, 1000));
      sub.add_option("--set", opt.overrides, "override a config value: key.path=value (repeatable)")->take_all()->expected(1);
    },
    run}};

}  // namespace
