#include "sphmol/run/restart_check.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <string_view>
#include <utility>

#include "sphmol/config/yaml_reader.hpp"

namespace sphmol {

namespace {

using Flat = std::vector<std::pair<std::string, std::string>>;

// key.path -> value text for every leaf (scalars, and sequences as one flow value).
void flatten(const YAML::Node& node, const std::string& prefix, Flat& out) {
  if (node.IsMap()) {
    for (const auto& kv : node) flatten(kv.second, prefix.empty() ? kv.first.as<std::string>() : prefix + "." + kv.first.as<std::string>(), out);
    return;
  }
  YAML::Emitter e;
  e << YAML::Flow << node;
  out.emplace_back(prefix, e.c_str());
}

// to_yaml always loads back; should it ever not, the restart is refused as bad input (a config
// error naming the config and the line), not a failed run.
Flat flat_config(const Config& c) {
  Flat out;
  flatten(parse_yaml(to_yaml(c), "the resolved config of " + (c.source.empty() ? std::string("--set values") : c.source)), "", out);
  return out;
}

}  // namespace

bool changes_physics(const std::string& key) {
  // Allowed: the end time, tolerances, step control and integrator table (the integrator itself must
  // match the checkpoint's integrator state, checked separately), the outputs (probes too), the health
  // limits (they end a run, never change its steps), and choices that give
  // bit-identical right-hand sides (neighbour search, skin, reordering, pair-pass layout).
  constexpr std::array<std::string_view, 3> free_sections = {"time.", "output.", "health."};
  constexpr std::array<std::string_view, 6> free_keys = {"discretization.neighbor_search", "discretization.skin",
                                                         "discretization.reorder", "discretization.pair_passes",
                                                         "discretization.combine_terms", "probes"};
  for (const auto s : free_sections)
    if (key.rfind(s, 0) == 0) return false;
  return std::find(free_keys.begin(), free_keys.end(), key) == free_keys.end();
}

std::vector<ConfigChange> config_changes(const Config& before, const Config& after) {
  const Flat a = flat_config(before), b = flat_config(after);
  const auto find = [](const Flat& f, const std::string& key) -> const std::string* {
    for (const auto& [k, v] : f)
      if (k == key) return &v;
    return nullptr;
  };
  std::vector<ConfigChange> out;
  for (const auto& [k, v] : a) {
    const std::string* w = find(b, k);
    if (!w || *w != v) out.push_back({k, v, w ? *w : "(absent)"});
  }
  for (const auto& [k, w] : b)
    if (!find(a, k)) out.push_back({k, "(absent)", w});
  return out;
}

void check_restart(const Checkpoint& cp, const Config& config, const std::string& checkpoint_dir,
                   bool allow_physics_change) {
  const std::string where = (std::filesystem::path(checkpoint_dir) / "checkpoint.json").string() + ": ";
  // At t_end there is nothing to integrate, but the run's end can still be done: a run stopped by a
  // signal while it plotted left such a checkpoint.
  if (!(cp.t <= config.time.t_end))
    throw CheckpointError(where + "t_bits: the checkpoint is at t = " + std::to_string(cp.t) +
                          " s, after time.t_end = " + std::to_string(config.time.t_end) +
                          " s: nothing to continue (raise time.t_end with --set)");
  Config written;
  try {
    written = load_config_string(cp.config_yaml, {}, where + "config");
  } catch (const ConfigError& e) {
    throw CheckpointError(where + "config: the config stored in the checkpoint does not load: " + e.what());
  }
  if (allow_physics_change) return;
  std::string changed;
  for (const auto& c : config_changes(written, config))
    if (changes_physics(c.key)) changed += (changed.empty() ? "" : ", ") + c.key + " (" + c.before + " -> " + c.after + ")";
  if (!changed.empty())
    throw CheckpointError(where + "config: the restart changes the physics the state was computed with: " + changed +
                          "; keep the checkpoint's values, or give --force-physics-change to continue this state "
                          "under the new settings");
}

}  // namespace sphmol
