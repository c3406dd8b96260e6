#pragma once
// One run of a study: the case in memory (no files), its summary, and "the error": the case's
// primary final error (Case::primary_error, e.g. e_rms for the channels); +inf for a blown-up run.
// A run that throws (other than the blow-up detection, which ends it cleanly) is reported as blown up
// with "run failed: <message>" as its cause.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol {

struct StudyRun {
  nlohmann::json summary;
  double error = 0.0;
  // CPU time of this process during the run (all threads). On a shared machine it varies less than
  // wall time, which other jobs stretch.
  double cpu_seconds = 0.0;
  bool blown_up = false;
  std::vector<double> final_state;  // y at t_end (empty if blown up)
  std::string note;                 // why a completed run has no error (primary error not measured)
};

StudyRun run_study_case(const Config& config);

// Whether the case's primary error is against an exact reference (Case::has_exact_reference); a case
// without one has a quantity there, which the studies compare with a finer run.
bool case_has_exact_reference(const Config& config);

// |value - reference| / |reference| (|value - reference| when the reference is 0); +inf for a
// non-finite value.
double relative_difference(double value, double reference);

// The case's CFL step at t = 0: the built system's stable_step after one RHS evaluation of the
// initial state (time.cfl coefficients of the config). Throws like run_case on an unknown case.
double initial_stable_step(const Config& config);

// The reference integrator of the time studies (converge --refine time, compare --reference-dt):
// ARKODE Verner 8(5)6, order 6, at a fixed step.
inline constexpr const char* kReferenceTable = "ARKODE_VERNER_8_5_6";

// rms over all fluid velocity components of (y - yref), relative to max |v_ref| (n fluid particles
// in `dimension` dimensions, state layout of core/state_layout.hpp); +inf if the sizes differ.
double relative_velocity_error(const std::vector<double>& y, const std::vector<double>& yref, int dimension, std::size_t n);

// max |v| over the fluid velocity components of y (layout as above); 0 if y is too short.
double max_abs_velocity(const std::vector<double>& y, int dimension, std::size_t n);

// Formats a number for CSV/labels with 6 significant digits.
std::string fmt(double x);
// A CSV cell: fmt(x), or empty where x is not finite (not measured: a blown-up run, an order without
// two clean levels), as the JSON has null there; pandas reads an empty cell as NaN.
std::string csv_number(double x);

}  // namespace sphmol
