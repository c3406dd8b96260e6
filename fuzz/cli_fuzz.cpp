// libFuzzer target for the command line of the run command and its --set path: the parsing and checks
// of main.cpp (apps/sph-mol/command_line.hpp) and the config they resolve, without running a case.
// Any argument vector must end in an exit code or a config, never in another exception, a crash or a
// sanitizer report.
// Input layout: YAML text, '\0', then the arguments, one per line (at most 32). The argument
// "@config" stands for a file holding the YAML text and "@checkpoint" for a directory whose
// config.yaml it is (what --restart reads), so both config paths are reached.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../apps/sph-mol/command_line.hpp"

namespace {
const std::filesystem::path& scratch() {
  static const std::filesystem::path dir = [] {
    std::string templ = (std::filesystem::temp_directory_path() / "sphmol-cli-fuzz.XXXXXX").string();
    if (!::mkdtemp(templ.data())) std::abort();
    return std::filesystem::path(templ);
  }();
  return dir;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const auto nul = input.find('\0');
  const std::string yaml = input.substr(0, nul);
  const std::string config_file = (scratch() / "config.yaml").string();
  std::ofstream(config_file, std::ios::binary | std::ios::trunc) << yaml;  // no fsync: thousands of inputs a second

  std::vector<std::string> args = {"sph-mol"};
  if (nul != std::string::npos) {
    std::size_t start = nul + 1;
    while (start <= input.size() && args.size() < 33) {
      const auto nl = input.find('\n', start);
      std::string a = input.substr(start, nl == std::string::npos ? std::string::npos : nl - start);
      if (a == "@config") a = config_file;
      if (a == "@checkpoint") a = scratch().string();
      args.push_back(std::move(a));
      if (nl == std::string::npos) break;
      start = nl + 1;
    }
  }
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());

  CLI::App app{"sph-mol"};
  app.set_version_flag("--version", "fuzz");
  app.require_subcommand(0, 1);
  sphmol::app::RunCommand cmd;
  sphmol::app::add_run_options(app, cmd);
  // A subcommand of its own, so the check of run-command options given before one is reached.
  std::string sub_output;
  app.add_subcommand("study", "a subcommand")->add_option("--output", sub_output);
  std::ostringstream out, err;
  if (sphmol::app::parse_command_line(app, static_cast<int>(argv.size()), argv.data(), out, err)) return 0;
  if (app.got_subcommand("study")) return 0;
  const auto config = sphmol::app::resolve_run_config(app, cmd, err);
  if (config && config->time.t_end <= 0.0) std::abort();  // the loader validated it
  return 0;
}
