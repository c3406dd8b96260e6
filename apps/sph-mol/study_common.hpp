#pragma once
// Shared by the study subcommands (compare, converge, stability): load the config with --set
// overrides, reporting config errors like the main command (exit code 2).
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol::app {

inline std::optional<Config> load_study_config(const std::string& path, const std::vector<std::string>& overrides,
                                               const char* who) {
  try {
    Config c = load_config(path, overrides);
    for (const auto& n : c.notices) std::cerr << "sph-mol " << who << ": " << n << '\n';
    return c;
  } catch (const ConfigError& e) {
    std::cerr << "sph-mol " << who << ": config error: " << e.what() << '\n';
    return std::nullopt;
  }
}

}  // namespace sphmol::app
