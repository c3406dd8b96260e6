#pragma once
// Shared by the scene reader and builder tests: reads a `scene:` section from YAML text as the
// config file "scene.yaml" (line numbers are those of the text), and a minimal resolved config.
#include <yaml-cpp/yaml.h>

#include <string>

#include "sphmol/config/config.hpp"
#include "sphmol/config/yaml_reader.hpp"
#include "sphmol/scene/scene_builder.hpp"
#include "sphmol/scene/scene_reader.hpp"

namespace scene_test {

// `config_file` locates relative mesh files.
inline sphmol::SceneSpec read(const std::string& yaml, int dimension, const std::string& config_file = "scene.yaml") {
  sphmol::YamlOrigin origin("scene.yaml");
  const YAML::Node root = YAML::Load(yaml);
  sphmol::MapReader top(origin, root, "", root.Mark(), {"scene"});
  sphmol::MapReader scene = top.section("scene", sphmol::kSceneKeys);
  return sphmol::read_scene(scene, dimension, config_file);
}

// Water-like fluid, cubic spline at h = 1.3 dx, wall particles.
inline sphmol::Config config(int dimension, double spacing) {
  sphmol::Config c;
  c.dimension = dimension;
  c.fluid.density = 1000.0;
  c.fluid.kinematic_viscosity = 1e-6;
  c.fluid.eos.type = "linear_relative";
  c.fluid.eos.sound_speed = 20.0;
  c.fluid.body_force.assign(static_cast<std::size_t>(dimension), 0.0);
  c.discretization.spacing = spacing;
  return c;
}

// The ConfigError text of reading and building the scene, or "<no error>".
inline std::string error_of(const std::string& yaml, const sphmol::Config& c, const std::string& config_file = "scene.yaml") {
  try {
    const auto spec = read(yaml, c.dimension, config_file);
    if (c.dimension == 2) (void)sphmol::build_scene<2>(spec, c);
    else (void)sphmol::build_scene<3>(spec, c);
  } catch (const sphmol::ConfigError& e) {
    return e.what();
  }
  return "<no error>";
}

}  // namespace scene_test
