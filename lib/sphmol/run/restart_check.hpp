#pragma once
// What a restart must agree on with the checkpoint it continues: the checkpoint's time lies before
// time.t_end, and the physics is the one the state was computed with. The physics keys of the two
// resolved configs (the one stored in checkpoint.json and the one the restart runs with: the
// checkpoint's config.yaml, maybe edited, plus --set) are compared; a change is refused unless
// explicitly allowed (--force-physics-change). Keys that only control how far or how accurately the
// run goes or what it writes (time.*, output.*, the neighbour search and pair-loop choices, which give
// identical or equally valid results) may change.
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/run/checkpoint.hpp"

namespace sphmol {

struct ConfigChange {
  std::string key;     // key.path
  std::string before;  // YAML text of the value ("(absent)" if the key is missing)
  std::string after;
};

// Keys whose value differs between two resolved configs, in to_yaml order.
std::vector<ConfigChange> config_changes(const Config& before, const Config& after);
// False for the keys a restart may change (see above).
bool changes_physics(const std::string& key);

// Throws CheckpointError "DIR/checkpoint.json: field: message" if `cp` cannot be continued with
// `config` (time after t_end; physics changed and not allowed). A checkpoint at t_end is accepted: the
// restart does the run's end (summary, plots) again.
void check_restart(const Checkpoint& cp, const Config& config, const std::string& checkpoint_dir,
                   bool allow_physics_change);

}  // namespace sphmol
