#include "sphmol/run/checkpoint.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "sphmol/io/atomic_file.hpp"
#include "sphmol/io/double_codec.hpp"

namespace sphmol {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFormat = "sph-mol checkpoint 2";
constexpr const char* kPrefix = "checkpoint-";

// Keeps the two checkpoints with the latest times.
void prune(const std::string& directory) {
  std::vector<std::pair<double, fs::path>> found;
  for (const auto& e : fs::directory_iterator(directory)) {
    const std::string name = e.path().filename().string();
    if (!e.is_directory() || name.rfind(kPrefix, 0) != 0) continue;
    char* end = nullptr;
    const double t = std::strtod(name.c_str() + std::char_traits<char>::length(kPrefix), &end);
    if (end && *end == '\0') found.emplace_back(t, e.path());
  }
  std::sort(found.begin(), found.end());
  for (std::size_t i = 0; i + 2 < found.size(); ++i) fs::remove_all(found[i].second);
}

}  // namespace

std::string checkpoint_name(double t) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s%.10g", kPrefix, t);
  return buf;
}

std::string write_checkpoint(const std::string& directory, const Checkpoint& cp, const std::string& config_yaml) {
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
  j["rhs_evals"] = cp.rhs_evals;
  j["wall_seconds"] = cp.wall_seconds;
  j["rhs_seconds"] = cp.rhs_seconds;
  j["search_seconds"] = cp.search_seconds;
  j["files"] = cp.files;

  const std::string name = checkpoint_name(cp.t);
  const fs::path final_dir = fs::path(directory) / name;
  // A fresh, uniquely named directory (mkdtemp: never an existing one or a planted link).
  std::string templ = (fs::path(directory) / ("." + name + ".XXXXXX")).string();
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
  fs::remove_all(final_dir);  // same time written again (a rerun into the same directory)
  fs::rename(tmp_dir, final_dir);
  fsync_directory(directory);
  prune(directory);
  return final_dir.string();
}

Checkpoint read_checkpoint(const std::string& checkpoint_dir) {
  const fs::path file = fs::path(checkpoint_dir) / "checkpoint.json";
  std::ifstream in(file);
  if (!in) throw CheckpointError(file.string() + ": cannot open (is " + checkpoint_dir + " a checkpoint-<t> directory?)");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
    if (j.at("format").get<std::string>() != kFormat)
      throw CheckpointError(file.string() + ": unknown format '" + j["format"].get<std::string>() + "' (this build reads '" + kFormat + "')");
    Checkpoint cp;
    cp.case_name = j.at("case").get<std::string>();
    cp.dimension = j.at("dimension").get<int>();
    cp.t = decode_doubles(j.at("t_bits").get<std::string>()).at(0);
    cp.y = decode_doubles(j.at("state").get<std::string>());
    if (cp.y.size() != j.at("state_size").get<std::size_t>())
      throw CheckpointError(file.string() + ": state has " + std::to_string(cp.y.size()) + " values, expected " +
                            std::to_string(j["state_size"].get<std::size_t>()));
    cp.integrator = j.at("integrator").get<std::string>();
    cp.integrator_state = j.at("integrator_state");
    cp.errors = j.at("errors");
    cp.observers = j.at("observers");
    cp.rhs_evals = j.at("rhs_evals").get<long>();
    cp.wall_seconds = j.at("wall_seconds").get<double>();
    cp.rhs_seconds = j.at("rhs_seconds").get<double>();
    cp.search_seconds = j.at("search_seconds").get<double>();
    if (j.contains("files")) cp.files = j["files"].get<std::vector<std::string>>();
    return cp;
  } catch (const CheckpointError&) {
    throw;
  } catch (const std::exception& e) {
    throw CheckpointError(file.string() + ": not a valid checkpoint: " + e.what());
  }
}

}  // namespace sphmol
