#pragma once
// Stability map (sph-mol stability): the case is run over a grid of sound speed (fluid.eos.sound_speed
// x factor; for an ideal gas, initial pressures x factor^2, see scale_sound_speed) and step (with time.dt in the config: dt x factor, fixed step; otherwise all time.cfl
// coefficients x factor) and each run is classified:
//   blown_up    - the run ended with status "blown_up" (run/health_check.hpp: NaN/Inf, particle out of
//                 the domain, density <= 0, step collapse);
//   oscillating - the signed mean profile error e_signed (u_sph - u_exact averaged over the profile,
//                 / v0; channel cases), sampled at `samples` equally spaced times, swings about its own
//                 mean after the start-up (the first tenth of the samples is skipped): at least two
//                 sign changes of e_signed - mean while |e_signed - mean| > osc_threshold. This is the
//                 symmetric oscillation about the channel centre of Vukčević 2012, §9 / Vukčević et al. 2012, §5: the
//                 profile error stays mirror-symmetric and breathes in time instead of settling
//                 (measured at 10 particles across with c >= 1e-2 m/s, period ~8 s; README);
//                 A run whose max |e_signed| exceeds 1 (error larger than v0: unbounded growth that
//                 has not yet thrown a particle out) is counted as blown_up too;
//   stable      - otherwise.
// Cases without e_signed are classified stable / blown_up only. Writes stability.csv, stability.json,
// stability.png (map: sound speed vs step, one point style per class).
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol {

struct StabilityOptions {
  std::vector<double> sound_speed_factors{0.25, 0.5, 1.0, 2.0};
  std::vector<double> step_factors{0.5, 1.0, 2.0, 4.0};
  double osc_threshold = 0.002;  // in units of v0
  int samples = 20;
  std::string output_dir;
  std::ostream* log = nullptr;
};

// The classification of one run from its summary (exposed for tests).
struct StabilityClass {
  std::string label;  // stable | oscillating | blown_up | not_blown_up
  // Measured only from a run's e_signed (false: a case without one, or a run that blew up before
  // its samples were taken); the numbers below are then not written as values.
  bool signed_measured = false;  // max_abs_signed
  bool swings_measured = false;  // sign_changes, amplitude (the oscillation test ran)
  int sign_changes = 0;
  double max_abs_signed = 0.0;
  double amplitude = 0.0;  // half the range of e_signed - mean after the start-up
};
StabilityClass classify_run(const nlohmann::json& summary, double osc_threshold);

// Multiplies the sound speed by `factor`: fluid.eos.sound_speed, or for an ideal gas (the shock tube,
// whose c = sqrt(gamma p / rho) comes from the state) the initial pressures by factor^2. Returns the
// sound speed reported on the map (for an ideal gas: that of the left state). ConfigError when the
// case refuses the scaled scene (a shock tube whose faster waves reach its end walls before t_end).
double scale_sound_speed(Config& c, double factor);

nlohmann::json run_stability(const Config& base, const StabilityOptions& opt);

}  // namespace sphmol
