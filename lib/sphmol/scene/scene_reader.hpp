#pragma once
// Reads the `scene:` section (config/README.md, the scene case) into a SceneSpec, checking every key, type,
// length and shape against the dimension; errors are ConfigErrors "FILE:LINE: scene.key.path: what".
// Checks that need the spacing (empty fills, bodies outside the domain, whole numbers of spacings)
// are build_scene's (scene_builder.hpp), located by the `where` each element keeps.
#include <string>

#include "sphmol/config/yaml_reader.hpp"
#include "sphmol/scene/scene_spec.hpp"

namespace sphmol {

// The keys of the scene section itself.
inline const std::vector<std::string> kSceneKeys = {"domain", "fluid", "walls"};

// `scene` reads the section with kSceneKeys; `config_file` is the config's path, relative mesh files
// are found next to it. `dimension`: 2 or 3.
SceneSpec read_scene(MapReader& scene, int dimension, const std::string& config_file);

}  // namespace sphmol
