#pragma once
// Subcommands register themselves here (one file per subcommand), so main.cpp never changes
// when one is added. `setup` declares options on the CLI11 subcommand; `run` executes it.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace sphmol::app {

struct Subcommand {
  std::string name;
  std::string description;
  std::function<void(CLI::App&)> setup;
  std::function<int()> run;
};

inline std::vector<Subcommand>& subcommands() {
  static std::vector<Subcommand> list;
  return list;
}

struct RegisterSubcommand {
  explicit RegisterSubcommand(Subcommand s) { subcommands().push_back(std::move(s)); }
};

}  // namespace sphmol::app
