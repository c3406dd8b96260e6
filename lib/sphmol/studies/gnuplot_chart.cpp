#include "sphmol/studies/gnuplot_chart.hpp"

#include <cstdlib>
#include <iomanip>
#include <sstream>

#include "sphmol/io/atomic_file.hpp"

namespace sphmol {

std::string gnuplot_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

std::string draw_chart(const Chart& chart, const std::string& png_path) {
  const std::string stem = png_path.size() > 4 ? png_path.substr(0, png_path.size() - 4) : png_path;
  std::ostringstream dat;
  dat << std::setprecision(10);
  for (const auto& s : chart.series) {
    dat << "# " << s.title << '\n';
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (s.y[i] > 0 || !chart.logy) dat << s.x[i] << ' ' << s.y[i] << '\n';
    dat << "\n\n";  // gnuplot data-set separator (index)
  }
  write_file_atomically(stem + ".dat", dat.str());
  std::ostringstream gp;
  gp << "set terminal pngcairo size 900,600 noenhanced\n"
     << "set output " << gnuplot_quote(png_path) << "\n"
     << "set title " << gnuplot_quote(chart.title) << "\n"
     << "set xlabel " << gnuplot_quote(chart.xlabel) << "\nset ylabel " << gnuplot_quote(chart.ylabel) << "\n"
     << (chart.logx ? "set logscale x\n" : "") << (chart.logy ? "set logscale y\n" : "")
     << "set grid\nset key below\n"
     << "set offsets graph 0.02, graph 0.02, graph 0.05, graph 0.05\n"  // points on the axis range stay visible
     << (chart.tight ? "set autoscale fix\nset offsets graph 0.08, graph 0.08, graph 0.1, graph 0.1\n" : "");
  gp << "plot ";
  for (std::size_t k = 0; k < chart.series.size(); ++k)
    gp << (k ? ", " : "") << gnuplot_quote(stem + ".dat") << " index " << k << " with " << chart.style
       << (chart.series[k].color.empty() ? std::string() : " lc rgb " + gnuplot_quote(chart.series[k].color)) << " title "
       << gnuplot_quote(chart.series[k].title);
  // Constant functions rather than arrows: autoscaling then keeps the lines in view.
  for (std::size_t k = 0; k < chart.hlines.size(); ++k) {
    std::ostringstream v;
    v << std::setprecision(10) << chart.hlines[k];
    gp << (chart.series.empty() && k == 0 ? "" : ", ") << v.str() << " with lines dt 2 lc rgb 'gray40' title " << gnuplot_quote("error " + v.str());
  }
  gp << "\n";
  write_file_atomically(stem + ".gp", gp.str());
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0)
    return "gnuplot not found (install gnuplot-nox, see scripts/setup.sh)";
  const std::string cmd = "gnuplot " + gnuplot_quote(stem + ".gp") + " 2>" + gnuplot_quote(stem + ".gnuplot.log");
  if (std::system(cmd.c_str()) != 0) return "gnuplot failed, see " + stem + ".gnuplot.log";
  return {};
}

}  // namespace sphmol
