#pragma once
// The per-output-time files this run wrote (OutputSink::written), `<prefix><t>.csv` (profile_t0.5.csv,
// midline_t0.2.csv, ...), sorted by t. Cases' plots() read them to draw the output times.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sphmol/run/case.hpp"

namespace sphmol {

std::vector<std::pair<double, std::string>> timed_output_files(const OutputSink& out, std::string_view prefix);

}  // namespace sphmol
