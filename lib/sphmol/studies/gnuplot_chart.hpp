#pragma once
// Log-log line charts of the studies, drawn by gnuplot through the one driver (io/gnuplot.hpp): one
// line per series. The data (STEM.dat) and the script (STEM.gp) are written next to the PNG so the
// chart can be redrawn (`gnuplot STEM.gp` in the output directory); gnuplot's messages go to
// STEM.gnuplot.log. Titles, labels and series names are reduced to gnuplot_text's character set.
#include <string>
#include <vector>

namespace sphmol {

struct ChartSeries {
  std::string title;
  std::vector<double> x, y;
  std::string color{};  // gnuplot colour name or #rrggbb; empty: gnuplot's sequence
};

struct Chart {
  std::string title, xlabel, ylabel;
  bool logx = true, logy = true;
  std::vector<ChartSeries> series;
  std::string style = "linespoints";  // gnuplot "with" style; "points pointsize 2" for maps
  std::vector<double> hlines{};       // dashed horizontal reference lines (e.g. target errors)
  bool tight = false;                 // axes end at the data (plus a margin), not at whole decades
};

// The gnuplot script of `chart`, reading STEM.dat and writing STEM.png (relative names; STEM must be a
// plain file name, io/gnuplot.hpp).
std::string chart_script(const Chart& chart, const std::string& stem);

// Writes DIR/STEM.dat, DIR/STEM.gp and draws DIR/STEM.png. Returns an empty string on success,
// otherwise why no PNG was made (gnuplot missing or failing); the data files are kept.
std::string draw_chart(const Chart& chart, const std::string& dir, const std::string& stem);
// The studies' "problem" in place of a chart when the config says output.plots: false.
inline constexpr const char* kPlotsOff = "output.plots is false";

}  // namespace sphmol
