#pragma once
// The scene section back as YAML (top-level key `scene:` at column 0), every default filled in, for
// the resolved config written next to the results: read_scene of it gives the same SceneSpec.
#include <string>

#include "sphmol/scene/scene_spec.hpp"

namespace sphmol {

std::string scene_to_yaml(const SceneSpec& spec);

}  // namespace sphmol
