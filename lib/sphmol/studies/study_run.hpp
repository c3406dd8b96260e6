#pragma once
// One run of a study: the case in memory (no files), its summary, and "the error": the case's
// primary final error (Case::primary_error, e.g. e_rms for the channels); +inf for a blown-up run.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol {

struct StudyRun {
  nlohmann::json summary;
  double error = 0.0;
  bool blown_up = false;
  std::vector<double> final_state;  // y at t_end (empty if blown up)
};

StudyRun run_study_case(const Config& config);

// Formats a number for CSV/labels with 6 significant digits.
std::string fmt(double x);

}  // namespace sphmol
