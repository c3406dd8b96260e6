#pragma once
// Runs one verification case from a validated config: builds the scene, assembles the RHS,
// integrates to every output time, measures the error against the case's reference and writes
// DIR/summary.json , DIR/config.yaml (the resolved config) and profile CSVs.
#include <functional>
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol {

class RunPartitioner;

struct RunOptions {
  std::string output_dir;    // empty: config.output.directory
  bool write_files = true;
  std::ostream* log = nullptr;  // one line per output time; null = silent
  std::vector<double>* final_state = nullptr;  // if set: receives the state y at t_end (studies)
  std::ostream* progress = nullptr;  // live progress line (a terminal's stderr); null = none
  std::string restart_from;     // a checkpoint-<t> directory to continue from (run/checkpoint.hpp)
  bool force_physics_change = false;  // restart even if the config changes the physics (run/restart_check.hpp)
  // SIGINT/SIGTERM -> checkpoint + summary with "status": "interrupted" (over ranks: set on every rank).
  bool handle_signals = false;
  // If set: called on this rank after each step of the run loop with the time reached (tests raise
  // a signal at a chosen step with it).
  std::function<void(double t)> after_step;
  // The output folder may hold another run's summary: delete that run's files first (--overwrite).
  bool overwrite = false;
  // Set by run_case: a restart into the folder of its checkpoint continues that run's file list.
  bool continuing = false;
  // Set: the run is split over ranks (run/partitioned_run.hpp); only the root rank writes files.
  const RunPartitioner* partitioner = nullptr;
};

// 128 + the signal that interrupted the run (summary "signal"), or 0 if it completed.
int interrupted_exit_code(const nlohmann::json& summary);

// Returns the summary (also written to DIR/summary.json when write_files).
nlohmann::json run_case(const Config& config, const RunOptions& options = {});

}  // namespace sphmol
