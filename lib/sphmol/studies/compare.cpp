#include "sphmol/studies/compare.hpp"

#include <filesystem>
#include <limits>
#include <ostream>
#include <sstream>

#include "sphmol/io/atomic_file.hpp"
#include "sphmol/studies/gnuplot_chart.hpp"
#include "sphmol/studies/study_run.hpp"

namespace sphmol {

nlohmann::json run_compare(const Config& base, const CompareOptions& opt) {
  std::filesystem::create_directories(opt.output_dir);
  nlohmann::json runs = nlohmann::json::array();
  std::ostringstream csv;
  csv << "integrator,setting,wall_seconds,rhs_evals,steps,error,status\n";
  Chart chart{"error vs wall time: " + base.case_name, "wall time [s]", "error (" + std::string("primary final error") + ")", true, true, {}};
  for (const auto& spec : opt.integrators) {
    ChartSeries series{spec.label, {}, {}};
    const bool adaptive = spec.adaptive();
    const auto& sweep = adaptive ? opt.rtols : opt.step_factors;
    for (double s : sweep) {
      Config c = base;
      spec.apply(c.time);
      std::string setting;
      if (adaptive) {
        c.time.rtol = s;
        c.time.dt.reset();
        setting = "rtol=" + fmt(s);
      } else if (base.time.dt) {
        c.time.dt = *base.time.dt * s;
        setting = "dt=" + fmt(*c.time.dt);
      } else {
        c.time.cfl.acoustic *= s;
        c.time.cfl.force *= s;
        c.time.cfl.viscous *= s;
        setting = "cfl_factor=" + fmt(s);
      }
      const StudyRun r = run_study_case(c);
      const auto& S = r.summary;
      const double wall = S["wall_seconds"].get<double>();
      csv << spec.label << ',' << setting << ',' << fmt(wall) << ',' << S["rhs_evals"] << ',' << S["steps"] << ','
          << fmt(r.error) << ',' << S["status"].get<std::string>() << '\n';
      runs.push_back({{"integrator", spec.label}, {"setting", setting}, {"wall_seconds", wall}, {"rhs_evals", S["rhs_evals"]},
                      {"steps", S["steps"]}, {"error", r.blown_up ? nlohmann::json(nullptr) : nlohmann::json(r.error)},
                      {"status", S["status"]}});
      if (opt.log)
        *opt.log << "compare: " << spec.label << ' ' << setting << ": error " << fmt(r.error) << ", wall " << fmt(wall)
                 << " s, " << S["rhs_evals"] << " RHS evaluations\n";
      if (!r.blown_up) {
        series.x.push_back(wall);
        series.y.push_back(r.error);
      }
    }
    chart.series.push_back(std::move(series));
  }
  nlohmann::json fastest = nlohmann::json::array();
  for (double target : opt.targets) {
    nlohmann::json best = nullptr;
    for (const auto& r : runs)
      if (!r["error"].is_null() && r["error"].get<double>() <= target &&
          (best.is_null() || r["wall_seconds"].get<double>() < best["wall_seconds"].get<double>()))
        best = r;
    fastest.push_back({{"target_error", target}, {"fastest", best}});
    if (opt.log)
      *opt.log << "compare: fastest at error <= " << fmt(target) << ": "
               << (best.is_null() ? std::string("none reached it")
                                  : best["integrator"].get<std::string>() + " " + best["setting"].get<std::string>() + " (" +
                                        fmt(best["wall_seconds"].get<double>()) + " s)")
               << '\n';
  }
  write_file_atomically(opt.output_dir + "/comparison.csv", csv.str());
  const std::string png = opt.output_dir + "/comparison.png";
  const std::string chart_problem = draw_chart(chart, png);
  nlohmann::json j{{"case", base.case_name}, {"config_file", base.source}, {"runs", runs}, {"fastest", fastest},
                   {"chart", chart_problem.empty() ? nlohmann::json("comparison.png") : nlohmann::json(nullptr)}};
  if (!chart_problem.empty()) {
    j["chart_problem"] = chart_problem;
    if (opt.log) *opt.log << "compare: no chart: " << chart_problem << '\n';
  }
  write_file_atomically(opt.output_dir + "/comparison.json", j.dump(2) + "\n");
  return j;
}

}  // namespace sphmol
