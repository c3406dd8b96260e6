#pragma once
// Helpers for tests that run the sph-mol binary (SPHMOL_BINARY): a fresh scratch directory, a
// command with its exit code and captured stderr, and reading a checkpoint's state.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace run_helpers {

namespace fs = std::filesystem;

inline fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("sphmol-it-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Result {
  int code;
  std::string err;
};

// Runs `SPHMOL_BINARY args` through the shell (args are quoted by the caller); `env` is prefixed
// (e.g. "PATH=/nonexistent").
inline Result sph_mol(const std::string& args, const fs::path& err_file, const std::string& env = "") {
  const std::string cmd = (env.empty() ? "" : "env " + env + " ") + std::string(SPHMOL_BINARY) + " " + args +
                          " >/dev/null 2>'" + err_file.string() + "'";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(err_file)};
}

inline nlohmann::json json_file(const fs::path& p) { return nlohmann::json::parse(slurp(p)); }

// Short Couette runs (20 particles across: 200 fluid particles, ~0.25 s per 0.1 s simulated).
inline std::string couette(const std::string& extra) {
  return "--config '" + std::string(SPHMOL_SOURCE_DIR) +
         "/verification/couette.yaml' --set discretization.particles_across=20 --set output.plots=false -q " + extra;
}

// Starts sph-mol with `args` (already split) without waiting, stderr to `err`; returns its pid (for
// tests that signal a running process).
inline pid_t spawn(const std::vector<std::string>& args, const fs::path& err) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::vector<char*> argv;
    std::string bin = SPHMOL_BINARY;
    argv.push_back(bin.data());
    std::vector<std::string> copy = args;
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::freopen(err.c_str(), "w", stderr);
    std::freopen("/dev/null", "w", stdout);
    ::execv(SPHMOL_BINARY, argv.data());
    ::_exit(127);
  }
  return pid;
}

}  // namespace run_helpers
