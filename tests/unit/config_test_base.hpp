#pragma once
// Shared fixture for the test_config_*.cpp files: a small valid config with known line numbers,
// and helpers to vary one line and capture the ConfigError text.
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace config_test {

// Line numbers are quoted by the error tests: keep this text unchanged.
inline const std::string base = R"(case: couette
dimension: 2
fluid:
  density: 1000
  kinematic_viscosity: 1.0e-6
  eos:
    sound_speed: 0.01
geometry:
  channel_height: 1.0e-3
  channel_length: 5.0e-4
  wall_velocity: 1.25e-5
discretization:
  particles_across: 20
time:
  t_end: 0.5
output:
  times: [0.1, 0.2]
)";

// `base` with the first occurrence of `from` replaced by `to` (which must exist).
inline std::string with(const std::string& from, const std::string& to, std::string text = base) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("test fixture: '" + from + "' not in config");
  return text.replace(at, from.size(), to);
}

// The error message of loading `yaml` as "case.yaml", or "<no error>".
inline std::string error_of(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  try {
    (void)sphmol::load_config_string(yaml, overrides, "case.yaml");
  } catch (const sphmol::ConfigError& e) {
    return e.what();
  }
  return "<no error>";
}

// The text of the shipped file verification/<name> (name with its .yaml).
inline std::string shipped(const std::string& name) {
  std::ifstream in(std::string(SPHMOL_SOURCE_DIR) + "/verification/" + name);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Whether one of the loader's notices contains `part`.
inline bool has_notice(const sphmol::Config& c, const std::string& part) {
  for (const auto& n : c.notices)
    if (n.find(part) != std::string::npos) return true;
  return false;
}

}  // namespace config_test
