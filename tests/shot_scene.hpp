#pragma once
// The outflow tests' scene: a block of fluid at rest, and one particle beside it at (0.31, 0.19)
// moving at 3 m/s towards the open face of the scene's box at x = 0.32; the solver's domain ends one
// wall layer further, at x = 0.34, which the particle crosses within about 0.01 s (h = 2 dx: the
// kernel support 0.08 reaches past it from the block's right column at x = 0.29). No body force
// unless `set` gives one; `more`: top-level YAML added to the file (probes).
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol::testing {

inline Config shot_scene(const std::vector<std::string>& set = {}, const std::string& more = "") {
  std::string yaml = R"yaml(case: scene
dimension: 2
fluid:
  density: 1000.0
  kinematic_viscosity: 0.0
  eos: {type: tait, sound_speed: 20.0, gamma: 7.0, clamp_negative: true}  # no tension holds the shot particle back
  body_force: [0.0, 0.0]
scene:
  domain: {lo: [0.0, 0.0], hi: [0.32, 0.4], boundaries: [open, open]}
  fluid:
    - shape: {type: box, lo: [0.1, 0.1], hi: [0.3, 0.3]}
    - shape: {type: box, lo: [0.3, 0.18], hi: [0.32, 0.2]}
      velocity: [3.0, 0.0]
discretization: {spacing: 0.02, smoothing_ratio: 2.0, wall_layers: 1, density: continuity, viscosity: none,
                 artificial_viscosity: {alpha: 0.1}}
time: {t_end: 0.1, integrator: leapfrog}
output: {times: [0.05, 0.1], plots: false, profiles: false}
)yaml";
  yaml += more;
  return load_config_string(yaml, set);
}

}  // namespace sphmol::testing
