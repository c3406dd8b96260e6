#pragma once
// Runs the cases' gnuplot scripts after a run. Each script is kept next to its PNG
// (plot_<name>.gp) so the plot can be redone or edited by hand. gnuplot missing or failing is a
// warning, never an error: the results themselves are already written.
#include <ostream>
#include <string>
#include <vector>

#include "sphmol/run/case.hpp"

namespace sphmol {

struct PlotResult {
  std::vector<std::string> written;   // PNG file names
  std::vector<std::string> warnings;  // one line each
};

PlotResult make_plots(const std::vector<PlotScript>& plots, const OutputSink& out);

}  // namespace sphmol
