#pragma once
// Checkpoints: DIR/checkpoint-<t>/ holds checkpoint.json (time, state, integrator state, the
// measurements so far, observer state; doubles as hex of their bits, so a restart starts from the
// identical state) and config.yaml (the resolved config, which `sph-mol --restart` loads). The
// directory is written under a temporary name, every file fsynced, then renamed into place: a
// killed run leaves either the old set of checkpoints or the new one, never a partial one. The
// two newest checkpoints are kept.
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace sphmol {

struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Checkpoint {
  std::string case_name;
  int dimension = 0;
  double t = 0.0;
  std::vector<double> y;
  std::string integrator;            // Integrator::name()
  nlohmann::json integrator_state;   // Integrator::save_state()
  nlohmann::json errors = nlohmann::json::array();  // measurements at output times <= t
  nlohmann::json observers = nlohmann::json::array();  // OutputObserver::save_state(), in order
  long rhs_evals = 0;
  double wall_seconds = 0.0;
  double rhs_seconds = 0.0, search_seconds = 0.0;  // the parts of wall_seconds in the RHS, in the search
  std::vector<std::string> files;  // the files the run had written to its output folder (OutputSink)
};

// "checkpoint-<t>" (t with 10 significant digits).
std::string checkpoint_name(double t);
// Writes DIR/checkpoint-<t>/ atomically and removes all but the two newest; returns its path.
std::string write_checkpoint(const std::string& directory, const Checkpoint& cp, const std::string& config_yaml);
// Reads DIR/checkpoint-<t>/checkpoint.json; throws CheckpointError naming the problem.
Checkpoint read_checkpoint(const std::string& checkpoint_dir);

}  // namespace sphmol
