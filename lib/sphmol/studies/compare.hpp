#pragma once
// Integrator comparison (sph-mol compare): the case is run with each integrator over a sweep of its
// accuracy setting, and error vs cost is tabulated (comparison.csv), charted (comparison.png, log-log
// error vs wall time, one line per integrator; comparison_cpu.png against CPU time) and summarised (comparison.json: per target error, the
// integrator that reaches it in the least wall time, the least CPU time, and the fewest RHS evaluations).
//   Sweeps: arkode_erk, cvode_adams: rtol in {1e-3, 1e-4, 1e-5, 1e-6, 1e-7} (atol from the config);
//   leapfrog, leapfrog_kdk: with time.dt in the config, dt x {1, 1/2, 1/4, 1/8}; otherwise the CFL step
//   with all time.cfl coefficients scaled by {1, 1/2, 1/4, 1/8}.
// The error of a run is the case's primary final error against its exact reference (e.g. e_rms for
// the channels, L1_rho for the shock tube): it includes the spatial error, so every integrator
// levels off at the discretisation's floor. With reference_dt the error is instead the time error
// alone: the relative rms velocity difference at t_end from a reference run of the same
// discretisation (ARKODE Verner 8(5)6 at the fixed step reference_dt), as in converge --refine time;
// the exact-reference error is still written (column exact_error).
// Per run the table also holds the step counts and the implicit solves' cost: rejected steps (error-test
// failures), the step attempts the CFL limit set (adaptive ARKODE integrators; empty otherwise), the
// implicit solves (leapfrog_imex: one viscous solve per step; arkode_imex: one per implicit stage),
// their Krylov iterations, and those per step and per solve. The explicit integrators have 0 solves
// and 0 iterations, and an empty iterations-per-solve cell (null in comparison.json). The log ends
// with the runs as a text table.
// "Fastest at a target error": studies/fastest_at_error.hpp (interpolated on each curve).
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/studies/integrator_spec.hpp"

namespace sphmol {

struct CompareOptions {
  std::vector<IntegratorSpec> integrators;
  std::string output_dir;
  std::vector<double> rtols{1e-3, 1e-4, 1e-5, 1e-6, 1e-7};
  std::vector<double> step_factors{1.0, 0.5, 0.25, 0.125};
  std::vector<double> targets{1e-2, 1e-3};
  std::optional<double> reference_dt;  // set: error against a Verner-6 reference run at this fixed step
  std::ostream* log = nullptr;
};

nlohmann::json run_compare(const Config& base, const CompareOptions& opt);

}  // namespace sphmol
