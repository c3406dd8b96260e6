#include "sphmol/run/plots.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "sphmol/io/atomic_file.hpp"

namespace sphmol {

namespace {

// gnuplot on PATH, or "" (checked first so a missing program is one clear warning).
std::string find_gnuplot() {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/gnuplot";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

// Runs `gnuplot script` inside `dir`; returns its exit status (-1 if it could not run).
int run_gnuplot(const std::string& gnuplot, const std::string& dir, const std::string& script) {
  const pid_t pid = ::fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    ::execl(gnuplot.c_str(), "gnuplot", script.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

PlotResult make_plots(const std::vector<PlotScript>& plots, const OutputSink& out) {
  PlotResult r;
  if (!out.enabled || plots.empty()) return r;
  const std::string gnuplot = find_gnuplot();
  if (gnuplot.empty()) {
    r.warnings.push_back("output.plots: gnuplot not found on PATH, no plots made (install gnuplot-nox; "
                         "the data files are written)");
    return r;
  }
  for (const auto& p : plots) {
    const std::string stem = std::filesystem::path(p.png).stem().string();
    const std::string script = "plot_" + stem + ".gp";
    write_file_atomically(out.path(script), p.script);
    std::filesystem::remove(out.path(p.png));
    const int status = run_gnuplot(gnuplot, out.directory, script);
    if (status == 0 && std::filesystem::exists(out.path(p.png)))
      r.written.push_back(p.png);
    else
      r.warnings.push_back("output.plots: gnuplot failed on " + out.path(script) + " (exit status " +
                           std::to_string(status) + "), no " + p.png);
  }
  return r;
}

}  // namespace sphmol
