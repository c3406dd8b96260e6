#include "sphmol/studies/gnuplot_chart.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "sphmol/io/atomic_file.hpp"
#include "sphmol/io/gnuplot.hpp"

namespace sphmol {

namespace {
// A colour is a name or #rrggbb: anything else is dropped rather than quoted into the script.
bool plain_colour(const std::string& c) {
  if (c.empty()) return false;
  for (char ch : c)
    if (!((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '-' || ch == '#' || (ch >= 'A' && ch <= 'F'))) return false;
  return true;
}
}  // namespace

std::string chart_script(const Chart& chart, const std::string& stem) {
  const std::string dat = gnuplot_file(stem + ".dat");
  std::ostringstream gp;
  gp << "set terminal pngcairo size 900,600 noenhanced\n"
     << gnuplot_output_line(stem + ".png") << "set title " << gnuplot_text(chart.title) << "\n"
     << "set xlabel " << gnuplot_text(chart.xlabel) << "\nset ylabel " << gnuplot_text(chart.ylabel) << "\n"
     << (chart.logx ? "set logscale x\n" : "") << (chart.logy ? "set logscale y\n" : "")
     << "set grid\nset key below\n"
     << "set offsets graph 0.02, graph 0.02, graph 0.05, graph 0.05\n"  // points on the axis range stay visible
     << (chart.tight ? "set autoscale fix\nset offsets graph 0.08, graph 0.08, graph 0.1, graph 0.1\n" : "");
  gp << "plot ";
  for (std::size_t k = 0; k < chart.series.size(); ++k)
    gp << (k ? ", " : "") << dat << " index " << k << " with " << chart.style
       << (plain_colour(chart.series[k].color) ? " lc rgb '" + chart.series[k].color + "'" : std::string()) << " title "
       << gnuplot_text(chart.series[k].title);
  // Constant functions rather than arrows: autoscaling then keeps the lines in view.
  for (std::size_t k = 0; k < chart.hlines.size(); ++k) {
    std::ostringstream v;
    v << std::setprecision(10) << chart.hlines[k];
    gp << (chart.series.empty() && k == 0 ? "" : ", ") << v.str() << " with lines dt 2 lc rgb 'gray40' title "
       << gnuplot_text("error " + v.str());
  }
  gp << "\n";
  return gp.str();
}

std::string draw_chart(const Chart& chart, const std::string& dir, const std::string& stem) {
  std::ostringstream dat;
  dat << std::setprecision(10);
  for (const auto& s : chart.series) {
    // A comment line per data set: the title without line breaks, which would start a data line.
    std::string title = s.title;
    for (char& c : title)
      if (c == '\n' || c == '\r') c = ' ';
    dat << "# " << title << '\n';
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (std::isfinite(s.y[i]) && (s.y[i] > 0 || !chart.logy)) dat << s.x[i] << ' ' << s.y[i] << '\n';
    dat << "\n\n";  // gnuplot data-set separator (index)
  }
  write_file_atomically(dir + "/" + stem + ".dat", dat.str());
  const std::string script = chart_script(chart, stem);
  const std::string gnuplot = find_gnuplot();
  if (gnuplot.empty()) {
    write_file_atomically(dir + "/" + stem + ".gp", script);
    return "gnuplot not found (install gnuplot-nox, see scripts/setup.sh)";
  }
  const GnuplotOutcome g = run_gnuplot(gnuplot, dir, stem + ".gp", script, stem + ".png");
  return g.ok ? std::string() : g.problem;
}

}  // namespace sphmol
