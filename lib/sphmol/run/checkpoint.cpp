#include "sphmol/run/checkpoint.hpp"

#include <fcntl.h>
#include <stdio.h>  // renameat2
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "sphmol/io/atomic_file.hpp"
#include "sphmol/io/double_codec.hpp"
#include "sphmol/io/input_file.hpp"
#include "sphmol/io/links.hpp"

namespace sphmol {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFormat = "sph-mol checkpoint 3";
constexpr const char* kPrefix = "checkpoint-";
// A checkpoint nests a few levels (integrator and observer state); deeper input is not one, and
// nesting without bound would exhaust the stack in the recursive copies and dumps of nlohmann::json.
constexpr int kMaxJsonDepth = 64;
// The state is 16 hex digits per double: 4 GiB holds tens of millions of particles.
constexpr std::uintmax_t kMaxCheckpointBytes = std::uintmax_t{4} << 30;

// Only a real checkpoint directory of `directory` (no link, the expected name) is ever removed.
bool removable_checkpoint(const fs::path& p, const fs::path& directory) {
  std::error_code ec;
  return p.parent_path() == directory && p.filename().string().rfind(kPrefix, 0) == 0 &&
         fs::symlink_status(p, ec).type() == fs::file_type::directory;
}

// The list after pruning: the last two distinct checkpoints of `written` in `directory` (the same
// time written again, by a rerun, counts once, at its latest position). Entries elsewhere (a restart
// from another directory) leave the list and are never removed.
std::vector<std::string> kept_checkpoints(const fs::path& directory, const std::vector<std::string>& written) {
  std::vector<std::string> here;
  for (const auto& w : written)
    if (fs::path(w).parent_path() == directory) {
      here.erase(std::remove(here.begin(), here.end(), w), here.end());
      here.push_back(w);
    }
  if (here.size() > 2) here.erase(here.begin(), here.end() - 2);
  return here;
}

// Puts `tmp_dir` in place of `final_dir`. An existing checkpoint of the same name (the same time written
// again) is exchanged atomically with the new one and then removed, so no moment is without it.
void install(const fs::path& tmp_dir, const fs::path& final_dir) {
  std::error_code ec;
  if (fs::symlink_status(final_dir, ec).type() != fs::file_type::not_found) {
    if (::renameat2(AT_FDCWD, tmp_dir.c_str(), AT_FDCWD, final_dir.c_str(), RENAME_EXCHANGE) == 0) {
      fs::remove_all(tmp_dir);  // now the old checkpoint
      return;
    }
    fs::remove_all(final_dir);  // a file system without RENAME_EXCHANGE
  }
  fs::rename(tmp_dir, final_dir);
}

}  // namespace

std::string checkpoint_name(double t) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s%.10g", kPrefix, t);
  return buf;
}

std::string write_checkpoint(const std::string& directory, const Checkpoint& cp, const std::string& config_yaml,
                             std::vector<std::string>& written) {
  // weakly_canonical resolves links: the run's folder was refused as a link when claimed
  // (run/output_folder.hpp), so one here was put in its place since; links higher up are layout.
  if (const auto link = final_link_message(directory)) throw std::runtime_error("cannot write a checkpoint: " + *link);
  const fs::path dir = fs::weakly_canonical(fs::absolute(directory));
  const std::string name = checkpoint_name(cp.t);
  const fs::path final_dir = dir / name;
  std::vector<std::string> all = written;
  all.push_back(final_dir.string());
  const std::vector<std::string> kept = kept_checkpoints(dir, all);

  nlohmann::json j;
  j["format"] = kFormat;
  j["case"] = cp.case_name;
  j["dimension"] = cp.dimension;
  j["t"] = cp.t;  // for people; the exact value is t_bits
  j["t_bits"] = encode_doubles({cp.t});
  j["state_size"] = cp.y.size();
  j["state"] = encode_doubles(cp.y);
  j["integrator"] = cp.integrator;
  j["integrator_state"] = cp.integrator_state;
  j["errors"] = cp.errors;
  j["observers"] = cp.observers;
  j["case_state"] = cp.case_state;
  j["rhs_evals"] = cp.rhs_evals;
  j["wall_seconds"] = cp.wall_seconds;
  j["rhs_seconds"] = cp.rhs_seconds;
  j["search_seconds"] = cp.search_seconds;
  j["config"] = config_yaml;
  j["written"] = kept;  // so a restart continues the list
  j["files"] = cp.files;

  // A fresh, uniquely named directory (mkdtemp: never an existing one or a planted link).
  std::string templ = (dir / ("." + name + ".XXXXXX")).string();
  if (!::mkdtemp(templ.data())) throw std::runtime_error("cannot create a checkpoint directory in " + directory);
  ::chmod(templ.c_str(), 0755);
  const fs::path tmp_dir = templ;
  try {
    write_file_atomically((tmp_dir / "config.yaml").string(), config_yaml);
    write_file_atomically((tmp_dir / "checkpoint.json").string(), j.dump() + "\n");
  } catch (...) {
    // A full disk or a file size limit: no half-written checkpoint is left, and the earlier ones stay.
    std::error_code ec;
    fs::remove_all(tmp_dir, ec);
    throw;
  }
  fsync_directory(tmp_dir.string());
  install(tmp_dir, final_dir);
  fsync_directory(dir.string());
  for (const auto& w : all)
    if (std::find(kept.begin(), kept.end(), w) == kept.end() && removable_checkpoint(w, dir)) {
      std::error_code ec;
      fs::remove_all(w, ec);  // best effort: the new checkpoint is in place
    }
  written = kept;
  return final_dir.string();
}

Checkpoint read_checkpoint(const std::string& checkpoint_dir) {
  // A linked checkpoint folder would also make the run continue in the link's folder, not the run's.
  if (const auto link = final_link_message(checkpoint_dir)) throw CheckpointError("--restart " + *link);
  const fs::path file = fs::path(checkpoint_dir) / "checkpoint.json";
  const std::string where = file.string() + ": ";
  std::string text;
  try {
    text = read_input_file(file.string(), kMaxCheckpointBytes, "checkpoint");
  } catch (const InputFileError& e) {
    throw CheckpointError(std::string(e.what()) + " (is " + checkpoint_dir + " a checkpoint-<t> directory?)");
  }
  const auto bad = [&](const std::string& field, const std::string& why) { return CheckpointError(where + field + ": " + why); };
  try {
    const nlohmann::json j = nlohmann::json::parse(text, [&](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
      if (depth > kMaxJsonDepth)
        throw CheckpointError(where + "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels: not a checkpoint");
      return true;
    });
    if (!j.is_object()) throw bad("(top level)", "not a JSON object");
    if (j.at("format").get<std::string>() != kFormat)
      throw CheckpointError(where + "unknown format '" + j["format"].get<std::string>() + "' (this build reads '" + kFormat + "')");
    Checkpoint cp;
    cp.case_name = j.at("case").get<std::string>();
    cp.dimension = j.at("dimension").get<int>();
    if (cp.dimension < 1 || cp.dimension > 3) throw bad("dimension", std::to_string(cp.dimension) + " is not 1, 2 or 3");
    cp.t = decode_doubles(j.at("t_bits").get<std::string>()).at(0);
    if (!std::isfinite(cp.t) || cp.t < 0.0) throw bad("t_bits", "time " + std::to_string(cp.t) + " is not a finite time >= 0");
    cp.y = decode_doubles(j.at("state").get<std::string>());
    if (cp.y.size() != j.at("state_size").get<std::size_t>())
      throw bad("state", std::to_string(cp.y.size()) + " values, expected " + std::to_string(j["state_size"].get<std::size_t>()));
    for (std::size_t k = 0; k < cp.y.size(); ++k)
      if (!std::isfinite(cp.y[k])) throw bad("state", "value " + std::to_string(k) + " is " + std::to_string(cp.y[k]) + ", not finite");
    cp.integrator = j.at("integrator").get<std::string>();
    cp.integrator_state = j.at("integrator_state");
    if (!cp.integrator_state.is_object()) throw bad("integrator_state", "not an object");
    // Step counters continue in the summary: a negative or fractional one is not a checkpoint's.
    for (const auto& [key, value] : cp.integrator_state.items()) {
      const bool counter = key == "steps" || (key.size() > 6 && key.compare(key.size() - 6, 6, "_steps") == 0);
      if (counter && !(value.is_number_unsigned() || (value.is_number_integer() && value.get<long>() >= 0)))
        throw bad("integrator_state." + key, value.dump() + " is not a count >= 0");
    }
    cp.errors = j.at("errors");
    if (!cp.errors.is_array()) throw bad("errors", "not an array");
    cp.observers = j.at("observers");
    if (!cp.observers.is_array()) throw bad("observers", "not an array");
    // Optional: older checkpoints of this format have none (the run says what that means).
    cp.case_state = j.contains("case_state") ? j["case_state"] : nlohmann::json();
    if (!cp.case_state.is_null() && !cp.case_state.is_object()) throw bad("case_state", "not an object");
    cp.rhs_evals = j.at("rhs_evals").get<long>();
    if (cp.rhs_evals < 0) throw bad("rhs_evals", std::to_string(cp.rhs_evals) + " < 0");
    for (const auto& [key, value] : {std::pair{"wall_seconds", &cp.wall_seconds}, std::pair{"rhs_seconds", &cp.rhs_seconds},
                                     std::pair{"search_seconds", &cp.search_seconds}}) {
      *value = j.at(key).get<double>();
      if (!std::isfinite(*value) || *value < 0.0) throw bad(key, std::to_string(*value) + " is not a finite time >= 0");
    }
    cp.config_yaml = j.at("config").get<std::string>();
    cp.written = j.at("written").get<std::vector<std::string>>();
    cp.wall_seconds = j.at("wall_seconds").get<double>();
    cp.rhs_seconds = j.at("rhs_seconds").get<double>();
    cp.search_seconds = j.at("search_seconds").get<double>();
    if (j.contains("files")) cp.files = j["files"].get<std::vector<std::string>>();
    return cp;
  } catch (const CheckpointError&) {
    throw;
  } catch (const std::exception& e) {
    throw CheckpointError(where + "not a valid checkpoint: " + e.what());
  }
}

}  // namespace sphmol
