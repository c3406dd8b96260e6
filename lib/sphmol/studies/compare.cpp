#include "sphmol/studies/compare.hpp"

#include <filesystem>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "sphmol/io/atomic_file.hpp"
#include "sphmol/studies/fastest_at_error.hpp"
#include "sphmol/studies/gnuplot_chart.hpp"
#include "sphmol/studies/study_run.hpp"

namespace sphmol {

nlohmann::json run_compare(const Config& base, const CompareOptions& opt) {
  std::filesystem::create_directories(opt.output_dir);
  nlohmann::json runs = nlohmann::json::array();
  std::ostringstream csv;
  csv << "integrator,setting,wall_seconds,rhs_evals,steps,error,exact_error,status\n";
  std::vector<double> ref_state;
  nlohmann::json reference = nullptr;
  if (opt.reference_dt) {
    Config rc = base;
    rc.time.integrator = "arkode_erk";
    rc.time.table = kReferenceTable;
    rc.time.dt = *opt.reference_dt;
    const StudyRun ref = run_study_case(rc);
    if (ref.blown_up) throw std::runtime_error("compare: the reference run blew up: " + ref.summary["blow_up"].dump());
    ref_state = ref.final_state;
    reference = {{"table", kReferenceTable}, {"dt", *opt.reference_dt}, {"wall_seconds", ref.summary["wall_seconds"]},
                 {"exact_error", ref.error}};
    if (opt.log)
      *opt.log << "compare: reference " << kReferenceTable << " dt = " << fmt(*opt.reference_dt) << ": exact error "
               << fmt(ref.error) << " (" << fmt(ref.summary["wall_seconds"].get<double>()) << " s)\n";
  }
  Chart chart{"error vs wall time: " + base.case_name, "wall time [s]", "", true, true, {}};
  chart.hlines = opt.targets;
  std::string error_key;
  // Per integrator, in sweep order (coarse to fine): error against wall time and against RHS evaluations.
  std::vector<std::vector<CurvePoint>> by_wall, by_rhs;
  std::vector<std::vector<std::string>> settings;
  std::vector<std::vector<CurvePoint>> exact_by_wall, exact_by_rhs;  // the case's own error (reference mode)
  std::string exact_key;
  for (const auto& spec : opt.integrators) {
    ChartSeries series{spec.label, {}, {}};
    by_wall.emplace_back();
    by_rhs.emplace_back();
    exact_by_wall.emplace_back();
    exact_by_rhs.emplace_back();
    settings.emplace_back();
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
      const double error = !opt.reference_dt ? r.error
                           : r.blown_up    ? std::numeric_limits<double>::infinity()
                                           : relative_velocity_error(r.final_state, ref_state, base.dimension,
                                                                     S["particles"]["fluid"].get<std::size_t>());
      error_key = opt.reference_dt ? "relative velocity error vs reference run" : S.value("primary_error", "e_rms");
      by_wall.back().push_back({wall, error});
      by_rhs.back().push_back({S["rhs_evals"].get<double>(), error});
      exact_key = S.value("primary_error", "e_rms");
      exact_by_wall.back().push_back({wall, r.error});
      exact_by_rhs.back().push_back({S["rhs_evals"].get<double>(), r.error});
      settings.back().push_back(setting);
      csv << spec.label << ',' << setting << ',' << fmt(wall) << ',' << S["rhs_evals"] << ',' << S["steps"] << ','
          << fmt(error) << ',' << fmt(r.error) << ',' << S["status"].get<std::string>() << '\n';
      runs.push_back({{"integrator", spec.label}, {"setting", setting}, {"wall_seconds", wall}, {"rhs_evals", S["rhs_evals"]},
                      {"steps", S["steps"]}, {"error", r.blown_up ? nlohmann::json(nullptr) : nlohmann::json(error)},
                      {"exact_error", r.blown_up ? nlohmann::json(nullptr) : nlohmann::json(r.error)},
                      {"status", S["status"]}});
      if (opt.log)
        *opt.log << "compare: " << spec.label << ' ' << setting << ": error " << fmt(error) << ", wall " << fmt(wall)
                 << " s, " << S["rhs_evals"] << " RHS evaluations\n";
      if (!r.blown_up) {
        series.x.push_back(wall);
        series.y.push_back(error);
      }
    }
    chart.series.push_back(std::move(series));
  }
  chart.ylabel = "final " + error_key;
  // Fastest at each target: the wall time (and RHS evaluations) at which each integrator's curve
  // reaches the target, interpolated (studies/fastest_at_error.hpp); the smallest wall time wins.
  const auto fastest_at = [&](const std::vector<std::vector<CurvePoint>>& walls, const std::vector<std::vector<CurvePoint>>& rhs,
                              const std::string& key) {
    nlohmann::json fastest = nlohmann::json::array();
    for (double target : opt.targets) {
      nlohmann::json per = nlohmann::json::array(), best = nullptr;
      for (std::size_t k = 0; k < opt.integrators.size(); ++k) {
        const auto w = cost_at_error(walls[k], target), n = cost_at_error(rhs[k], target);
        nlohmann::json e{{"integrator", opt.integrators[k].label}};
        if (!w) {
          e["wall_seconds"] = nullptr;
          e["rhs_evals"] = nullptr;
        } else {
          e["wall_seconds"] = w->cost;
          e["rhs_evals"] = n ? nlohmann::json(n->cost) : nlohmann::json(nullptr);
          e["upper_bound"] = w->bound;  // the cheapest run already met the target
          e["first_setting_at_target"] = settings[k][w->below];
          if (best.is_null() || w->cost < best["wall_seconds"].get<double>()) best = e;
        }
        per.push_back(e);
      }
      nlohmann::json fewest = nullptr;
      for (const auto& e : per)
        if (!e["rhs_evals"].is_null() && (fewest.is_null() || e["rhs_evals"].get<double>() < fewest["rhs_evals"].get<double>()))
          fewest = e;
      fastest.push_back({{"target_error", target}, {"error", key}, {"fastest", best}, {"fewest_rhs_evals", fewest},
                         {"integrators", per}});
      if (opt.log) {
        const auto describe = [&](const nlohmann::json& e) {
          return e.is_null() ? std::string("no integrator reached it")
                             : e["integrator"].get<std::string>() + " (" + (e["upper_bound"].get<bool>() ? "<= " : "") +
                                   fmt(e["wall_seconds"].get<double>()) + " s, " +
                                   (e["rhs_evals"].is_null() ? std::string("?") : fmt(e["rhs_evals"].get<double>())) +
                                   " RHS evaluations)";
        };
        *opt.log << "compare: fastest at " << key << " = " << fmt(target) << ": " << describe(best)
                 << "; fewest RHS evaluations: " << describe(fewest) << '\n';
      }
    }
    return fastest;
  };
  const nlohmann::json fastest = fastest_at(by_wall, by_rhs, error_key);
  // With a reference run, the same summary for the exact-reference error (time + space error).
  nlohmann::json fastest_exact = nullptr;
  if (opt.reference_dt) fastest_exact = fastest_at(exact_by_wall, exact_by_rhs, exact_key);
  write_file_atomically(opt.output_dir + "/comparison.csv", csv.str());
  const std::string png = opt.output_dir + "/comparison.png";
  const std::string chart_problem = draw_chart(chart, png);
  nlohmann::json j{{"case", base.case_name}, {"error", error_key}, {"reference_run", reference}, {"config_file", base.source}, {"runs", runs}, {"fastest", fastest},
                   {"fastest_exact_error", fastest_exact},
                   {"chart", chart_problem.empty() ? nlohmann::json("comparison.png") : nlohmann::json(nullptr)}};
  if (!chart_problem.empty()) {
    j["chart_problem"] = chart_problem;
    if (opt.log) *opt.log << "compare: no chart: " << chart_problem << '\n';
  }
  write_file_atomically(opt.output_dir + "/comparison.json", j.dump(2) + "\n");
  return j;
}

}  // namespace sphmol
