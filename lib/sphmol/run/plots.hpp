#pragma once
// Runs the cases' gnuplot scripts after a run, through the one gnuplot driver (io/gnuplot.hpp). Each
// script is kept next to its PNG (plot_<name>.gp, gnuplot's messages in plot_<name>.gnuplot.log) so
// the plot can be redone or edited by hand. gnuplot missing or failing is a warning, never an error:
// the results themselves are already written.
#include <functional>
#include <string>
#include <vector>

#include "sphmol/run/case.hpp"

namespace sphmol {

struct PlotResult {
  std::vector<std::string> written;   // PNG file names
  std::vector<std::string> warnings;  // one line each
  bool interrupted = false;           // `interrupted` turned true: gnuplot stopped, later plots skipped
};

// `interrupted` (may be empty) is polled while gnuplot runs (a pending SIGINT/SIGTERM).
PlotResult make_plots(const std::vector<PlotScript>& plots, const OutputSink& out,
                      const std::function<bool()>& interrupted = {});

}  // namespace sphmol
