#pragma once
// The per-output-time files this run wrote (OutputSink::written), `<prefix><t>.csv` (profile_t0.5.csv,
// midline_t0.2.csv, ...), sorted by t. Cases' plots() read them to draw the output times.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sphmol/run/case.hpp"

namespace sphmol {

// The time in those names: six significant digits (0.5, 0.0015, 1.23457e-05). The loader refuses
// output times that give one text, so no file of an output time overwrites another's.
std::string output_time_text(double t);

std::vector<std::pair<double, std::string>> timed_output_files(const OutputSink& out, std::string_view prefix);

}  // namespace sphmol
