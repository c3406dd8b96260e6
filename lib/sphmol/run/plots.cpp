#include "sphmol/run/plots.hpp"

#include <filesystem>

#include "sphmol/io/gnuplot.hpp"

namespace sphmol {

PlotResult make_plots(const std::vector<PlotScript>& plots, const OutputSink& out, const std::function<bool()>& interrupted) {
  PlotResult r;
  if (!out.enabled || plots.empty()) return r;
  const std::string gnuplot = find_gnuplot();
  if (gnuplot.empty()) {
    r.warnings.push_back("output.plots: gnuplot not found on PATH, no plots made (install gnuplot-nox; "
                         "the data files are written)");
    return r;
  }
  for (const auto& p : plots) {
    if (interrupted && interrupted()) {
      r.interrupted = true;
      break;
    }
    const std::string script = "plot_" + std::filesystem::path(p.png).stem().string() + ".gp";
    const GnuplotOutcome g = run_gnuplot(gnuplot, out.directory, script, p.script, p.png, interrupted);
    // The run's own files (summary "files", --overwrite): the script and gnuplot's log always, the PNG
    // when it was made.
    out.record(script);
    out.record(std::filesystem::path(script).stem().string() + ".gnuplot.log");
    if (g.ok) {
      out.record(p.png);
      r.written.push_back(p.png);
      continue;
    }
    r.warnings.push_back("output.plots: no " + p.png + ": " + g.problem);
    if (g.interrupted) {
      r.interrupted = true;
      break;
    }
  }
  return r;
}

}  // namespace sphmol
