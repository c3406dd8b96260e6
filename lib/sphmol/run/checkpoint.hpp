#pragma once
// Checkpoints: DIR/checkpoint-<t>/ holds checkpoint.json (time, state, integrator state, the
// measurements so far, the case's and the observers' state; doubles as hex of their bits, so a
// restart starts from the identical state; the resolved config it was written with; the checkpoints
// this run wrote) and config.yaml (the same resolved config, which `sph-mol --restart` loads). The
// directory is written under a temporary name, every file fsynced, then renamed into place: a killed
// run leaves either the old set of checkpoints or the new one, never a partial one. Of the
// checkpoints this run wrote (a restarted run continues its predecessor's list when it writes to the
// same directory), the two latest are kept; a checkpoint the run did not write is never removed,
// whatever its time.
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
  // Case::save_state(); read back as null from a checkpoint written before cases had one.
  nlohmann::json case_state = nlohmann::json::object();
  long rhs_evals = 0;
  double wall_seconds = 0.0;
  double rhs_seconds = 0.0, search_seconds = 0.0;  // the parts of wall_seconds in the RHS, in the search
  // Read back only: the resolved config (to_yaml) the checkpoint was written with, and the checkpoint
  // directories (absolute paths, oldest first, this one last) the run had written and kept.
  std::string config_yaml;
  std::vector<std::string> written;
  std::vector<std::string> files;  // the files the run had written to its output folder (OutputSink)
};

// "checkpoint-<t>" (t with 10 significant digits).
std::string checkpoint_name(double t);
// Writes DIR/checkpoint-<t>/ atomically; returns its path. `written`: the checkpoints this run wrote
// so far (start with the restarted checkpoint's `written`, or empty); the new one is appended and all
// but the last two in DIR are removed from the disk and from the list.
std::string write_checkpoint(const std::string& directory, const Checkpoint& cp, const std::string& config_yaml,
                             std::vector<std::string>& written);
// Reads DIR/checkpoint-<t>/checkpoint.json and checks what a restart relies on (a finite time >= 0,
// counters >= 0, a finite state); throws CheckpointError naming the file and the field.
Checkpoint read_checkpoint(const std::string& checkpoint_dir);

}  // namespace sphmol
