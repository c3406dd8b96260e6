#pragma once
// Runs one verification case from a validated config: builds the scene, assembles the RHS,
// integrates to every output time, measures the error against the case's reference and writes
// DIR/summary.json (SPEC §3), DIR/config.yaml (the resolved config) and profile CSVs.
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol {

struct RunOptions {
  std::string output_dir;    // empty: config.output.directory
  bool write_files = true;
  std::ostream* log = nullptr;  // one line per output time; null = silent
  std::vector<double>* final_state = nullptr;  // if set: receives the state y at t_end (studies)
};

// Returns the summary (also written to DIR/summary.json when write_files).
nlohmann::json run_case(const Config& config, const RunOptions& options = {});

}  // namespace sphmol
