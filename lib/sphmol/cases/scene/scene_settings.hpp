#pragma once
// The `scene` case's own settings: the scene section as read (scene/scene_spec.hpp).
#include "sphmol/config/config.hpp"
#include "sphmol/scene/scene_spec.hpp"
#include "sphmol/scene/scene_yaml.hpp"

namespace sphmol {

struct SceneSettings final : CaseSettings {
  SceneSpec spec;
  std::string to_yaml() const override { return scene_to_yaml(spec); }
  // Wall body k's particles carry Particles::body = k (scene/scene_builder.cpp).
  std::vector<std::string> wall_bodies() const override {
    std::vector<std::string> names;
    for (const auto& w : spec.walls) names.push_back(w.name);
    return names;
  }
};

}  // namespace sphmol
