// sph-mol command line: `sph-mol --config FILE` runs a case; subcommands (kernels, ...) register
// themselves through subcommand.hpp.
#include <CLI/CLI.hpp>

#include <iostream>

#include "sphmol/core/version.hpp"
#include "subcommand.hpp"

int main(int argc, char** argv) {
  CLI::App app{"sph-mol: smoothed particle hydrodynamics as a method of lines"};
  app.set_version_flag("--version", sphmol::version());
  app.require_subcommand(0, 1);
  for (auto& s : sphmol::app::subcommands()) {
    auto* sub = app.add_subcommand(s.name, s.description);
    s.setup(*sub);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  for (auto& s : sphmol::app::subcommands())
    if (app.got_subcommand(s.name)) return s.run();
  std::cout << app.help();
  return 0;
}
