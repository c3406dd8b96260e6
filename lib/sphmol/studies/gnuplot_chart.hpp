#pragma once
// Log-log line charts drawn by gnuplot (Debian gnuplot-nox, pngcairo or png terminal): one line per
// series. The data and the script are written next to the PNG so the chart can be redrawn.
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

// Writes PNG_PATH (and PNG_PATH minus ".png" plus ".dat"/".gp"). Returns an empty string on
// success, otherwise why no PNG was made (gnuplot missing or failing); the data files are kept.
std::string draw_chart(const Chart& chart, const std::string& png_path);

// Shell-safe single-quoted string for gnuplot commands.
std::string gnuplot_quote(const std::string& s);

}  // namespace sphmol
