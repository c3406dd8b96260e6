#include "sphmol/studies/compare.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "sphmol/io/atomic_file.hpp"
#include "sphmol/run/output_folder.hpp"
#include "sphmol/run/error_unit.hpp"
#include "sphmol/studies/fastest_at_error.hpp"
#include "sphmol/studies/gnuplot_chart.hpp"
#include "sphmol/studies/study_run.hpp"

namespace sphmol {

namespace {

// One run of the sweep, as the fastest-at-error summary needs it.
struct SweepPoint {
  std::string setting;
  double wall = 0.0, cpu = 0.0, rhs = 0.0;
  double error = 0.0;        // the error of the study (time error with a reference run)
  double exact_error = 0.0;  // the case's primary error against its exact reference
};

// For each target: per integrator the interpolated wall time, CPU time and RHS evaluations at which
// its curve reaches the target (studies/fastest_at_error.hpp); the fastest by wall time, by CPU time,
// and the one with the fewest RHS evaluations.
nlohmann::json fastest_at_targets(const std::vector<IntegratorSpec>& specs, const std::vector<std::vector<SweepPoint>>& points,
                                  bool use_exact, const std::string& key, const std::vector<double>& targets, std::ostream* log) {
  nlohmann::json out = nlohmann::json::array();
  for (double target : targets) {
    nlohmann::json per = nlohmann::json::array();
    for (std::size_t k = 0; k < specs.size(); ++k) {
      std::vector<CurvePoint> wall, cpu, rhs;
      for (const auto& p : points[k]) {
        const double e = use_exact ? p.exact_error : p.error;
        wall.push_back({p.wall, e});
        cpu.push_back({p.cpu, e});
        rhs.push_back({p.rhs, e});
      }
      const auto w = cost_at_error(wall, target), c = cost_at_error(cpu, target), n = cost_at_error(rhs, target);
      nlohmann::json e{{"integrator", specs[k].label}, {"wall_seconds", nullptr}, {"cpu_seconds", nullptr}, {"rhs_evals", nullptr}};
      if (w) {
        e["wall_seconds"] = w->cost;
        e["upper_bound"] = w->bound;  // the cheapest run already met the target
        e["first_setting_at_target"] = points[k][w->below].setting;
      }
      if (c) e["cpu_seconds"] = c->cost;
      if (n) e["rhs_evals"] = n->cost;
      per.push_back(e);
    }
    const auto best_by = [&](const char* field) {
      nlohmann::json best = nullptr;
      for (const auto& e : per)
        if (!e[field].is_null() && (best.is_null() || e[field].get<double>() < best[field].get<double>())) best = e;
      return best;
    };
    const nlohmann::json fastest = best_by("wall_seconds"), fastest_cpu = best_by("cpu_seconds"), fewest = best_by("rhs_evals");
    out.push_back({{"target_error", target}, {"error", key}, {"fastest", fastest}, {"fastest_cpu", fastest_cpu},
                   {"fewest_rhs_evals", fewest}, {"integrators", per}});
    if (log) {
      const auto describe = [&](const nlohmann::json& e, const char* field, const char* unit) {
        if (e.is_null()) return std::string("no integrator reached it");
        return e["integrator"].get<std::string>() + " (" + (e["upper_bound"].get<bool>() ? "<= " : "") +
               fmt(e[field].get<double>()) + unit + ")";
      };
      *log << "compare: at " << key << " = " << fmt(target) << ": fastest (wall) " << describe(fastest, "wall_seconds", " s")
           << "; fastest (CPU) " << describe(fastest_cpu, "cpu_seconds", " s") << "; fewest RHS evaluations "
           << describe(fewest, "rhs_evals", "") << '\n';
    }
  }
  return out;
}

// A run's step and implicit-solve counts from its summary: the Krylov iterations and implicit
// solves of leapfrog_imex (one viscous solve per step) and arkode_imex (one per implicit stage), 0 for
// the explicit integrators; the CFL-limited step attempts of the adaptive ARKODE integrators.
struct RunCounts {
  long steps = 0, rejected = 0, solves = 0, krylov = 0;
  std::optional<long> stability_limited;
  double krylov_per_step() const { return steps > 0 ? static_cast<double>(krylov) / static_cast<double>(steps) : 0.0; }
  // No solves (an explicit integrator): none.
  std::optional<double> krylov_per_solve() const {
    if (solves <= 0) return std::nullopt;
    return static_cast<double>(krylov) / static_cast<double>(solves);
  }
};

RunCounts counts_of(const nlohmann::json& S) {
  const auto count = [](const nlohmann::json& j, const char* key) -> long {
    return j.is_object() && j.contains(key) && j[key].is_number() ? j[key].get<long>() : 0;
  };
  RunCounts c;
  c.steps = count(S, "steps");
  c.rejected = count(S, "rejected_steps");
  const nlohmann::json& I = S.contains("integrator") ? S["integrator"] : nlohmann::json(nullptr);
  c.solves = count(I, "implicit_solves");
  c.krylov = count(I, "krylov_iterations");
  if (I.is_object() && I.contains("stability_limited_steps")) c.stability_limited = count(I, "stability_limited_steps");
  return c;
}

// The runs as a text table for the log: cost, steps, implicit solves and error per run.
void print_run_table(std::ostream& log, const nlohmann::json& runs) {
  const std::vector<std::string> head{"integrator", "setting",     "CPU s",      "RHS",     "steps",    "rejected",
                                      "CFL-limited", "solves",     "Krylov its", "its/step", "its/solve", "error"};
  std::vector<std::vector<std::string>> rows{head};
  const auto num = [](const nlohmann::json& v) {
    if (v.is_null()) return std::string("-");
    if (v.is_number_integer()) return std::to_string(v.get<long>());
    return fmt(v.get<double>());
  };
  for (const auto& r : runs)
    rows.push_back({r["integrator"].get<std::string>(), r["setting"].get<std::string>(), num(r["cpu_seconds"]), num(r["rhs_evals"]),
                    num(r["steps"]), num(r["rejected_steps"]), num(r["stability_limited_steps"]), num(r["implicit_solves"]),
                    num(r["krylov_iterations"]), num(r["krylov_iterations_per_step"]), num(r["krylov_iterations_per_solve"]),
                    r["error"].is_null() ? std::string("blown up") : num(r["error"])});
  std::vector<std::size_t> width(head.size(), 0);
  for (const auto& row : rows)
    for (std::size_t k = 0; k < row.size(); ++k) width[k] = std::max(width[k], row[k].size());
  for (const auto& row : rows) {
    log << "compare: ";
    for (std::size_t k = 0; k < row.size(); ++k) {
      const std::string pad(width[k] - row[k].size(), ' ');
      log << (k < 2 ? row[k] + pad : pad + row[k]) << (k + 1 < row.size() ? "  " : "\n");
    }
  }
}

}  // namespace

nlohmann::json run_compare(const Config& base, const CompareOptions& opt) {
  // Locked for the study's lifetime: two studies into one folder would overwrite each other's files.
  if (opt.reference_dt && !(*opt.reference_dt < base.time.t_end))
    throw std::invalid_argument("--reference-dt " + fmt(*opt.reference_dt) + " s is not shorter than time.t_end = " + fmt(base.time.t_end) +
                                " s; the reference run needs a step well below the compared runs' steps");
  const OutputFolder folder(opt.output_dir, OutputFolder::Options{.lock_only = true});
  nlohmann::json runs = nlohmann::json::array();
  std::ostringstream csv;
  // The header follows the runs: the error units depend on the case's error measure.
  std::vector<double> ref_state;
  nlohmann::json reference = nullptr;
  // A case without an exact reference (a user scene) has a quantity as its primary error: every run
  // is measured against a reference run, at a quarter of the CFL step at t = 0 unless given.
  const bool exact = case_has_exact_reference(base);
  std::optional<double> reference_dt = opt.reference_dt;
  if (!exact && !reference_dt) {
    reference_dt = 0.25 * initial_stable_step(base);
    if (opt.log)
      *opt.log << "compare: case '" << base.case_name << "' has no exact reference; its runs are measured against a reference run "
               << "at dt = " << fmt(*reference_dt) << " s (a quarter of the CFL step at t = 0; --reference-dt sets it)\n";
  }
  double ref_value = 0.0;
  if (reference_dt) {
    Config rc = base;
    rc.time.integrator = "arkode_erk";
    rc.time.table = kReferenceTable;
    rc.time.dt = *reference_dt;
    const StudyRun ref = run_study_case(rc);
    if (ref.blown_up) throw std::runtime_error("the reference run blew up: " + ref.summary["blow_up"].dump());
    ref_state = ref.final_state;
    ref_value = ref.error;
    reference = {{"table", kReferenceTable}, {"dt", *reference_dt}, {"wall_seconds", ref.summary["wall_seconds"]},
                 {"exact_error", ref.error}};
    if (opt.log)
      *opt.log << "compare: reference " << kReferenceTable << " dt = " << fmt(*reference_dt) << ": exact error "
               << fmt(ref.error) << " (" << fmt(ref.summary["wall_seconds"].get<double>()) << " s)\n";
  }
  Chart chart{"error vs wall time: " + base.case_name, "wall time [s]", "", true, true, {}};
  chart.hlines = opt.targets;
  Chart cpu_chart{"error vs CPU time: " + base.case_name, "CPU time [s]", "", true, true, {}};
  cpu_chart.hlines = opt.targets;
  std::string error_key, exact_key;
  std::vector<std::vector<SweepPoint>> points;  // per integrator, in sweep order (coarse to fine)
  for (const auto& spec : opt.integrators) {
    ChartSeries series{spec.label, {}, {}}, cpu_series{spec.label, {}, {}};
    points.emplace_back();
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
      const double inf = std::numeric_limits<double>::infinity();
      const double error = !reference_dt ? r.error
                           : r.blown_up    ? inf
                                           : relative_velocity_error(r.final_state, ref_state, base.dimension,
                                                                     S["particles"]["fluid"].get<std::size_t>());
      if (exact) exact_key = S.value("primary_error", "e_rms");
      error_key = reference_dt ? "relative velocity error vs reference run" : exact_key;
      // Without an exact reference, the "exact" column is the quantity's difference from the reference run's.
      const double exact_error = exact ? r.error : r.blown_up ? inf : relative_difference(r.error, ref_value);
      if (!exact) exact_key = S.value("primary_error", "e_rms") + " relative to the reference run";
      points.back().push_back({setting, wall, r.cpu_seconds, S["rhs_evals"].get<double>(), error, exact_error});
      const RunCounts n = counts_of(S);
      const auto per_solve = n.krylov_per_solve();
      // Not applicable (no implicit solves; no CFL-limit count): an empty cell, null in the JSON.
      const auto cell = [](const auto& v) { return v ? fmt(static_cast<double>(*v)) : std::string(); };
      csv << spec.label << ',' << setting << ',' << fmt(wall) << ',' << fmt(r.cpu_seconds) << ',' << S["rhs_evals"] << ','
          << n.steps << ',' << n.rejected << ',' << cell(n.stability_limited) << ',' << n.solves << ',' << n.krylov << ','
          << fmt(n.krylov_per_step()) << ',' << cell(per_solve) << ',' << csv_number(error) << ',' << csv_number(exact_error) << ','
          << S["status"].get<std::string>() << '\n';
      const auto num = [&](double x) { return r.blown_up || !std::isfinite(x) ? nlohmann::json(nullptr) : nlohmann::json(x); };
      const auto opt_json = [](const auto& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
      runs.push_back({{"integrator", spec.label},
                      {"setting", setting},
                      {"wall_seconds", wall},
                      {"cpu_seconds", r.cpu_seconds},
                      {"rhs_evals", S["rhs_evals"]},
                      {"steps", S["steps"]},
                      {"rejected_steps", n.rejected},
                      {"stability_limited_steps", opt_json(n.stability_limited)},
                      {"implicit_solves", n.solves},
                      {"krylov_iterations", n.krylov},
                      {"krylov_iterations_per_step", n.krylov_per_step()},
                      {"krylov_iterations_per_solve", opt_json(per_solve)},
                      {"error", num(error)},
                      {"exact_error", num(exact_error)},
                      {"status", S["status"]}});
      if (opt.log) {
        *opt.log << "compare: " << spec.label << ' ' << setting << ": error " << fmt(error) << ", wall " << fmt(wall) << " s, CPU "
                 << fmt(r.cpu_seconds) << " s, " << S["rhs_evals"] << " RHS evaluations, " << n.steps << " steps";
        if (n.rejected > 0) *opt.log << " (" << n.rejected << " rejected)";
        if (n.solves > 0)
          *opt.log << ", " << n.krylov << " Krylov iterations (" << fmt(n.krylov_per_step()) << " per step, " << fmt(*per_solve)
                   << " per solve)";
        *opt.log << (r.note.empty() ? "" : "; " + r.note) << '\n';
      }
      if (!r.blown_up) {
        series.x.push_back(wall);
        series.y.push_back(error);
        cpu_series.x.push_back(r.cpu_seconds);
        cpu_series.y.push_back(error);
      }
    }
    chart.series.push_back(std::move(series));
    cpu_chart.series.push_back(std::move(cpu_series));
  }
  chart.ylabel = cpu_chart.ylabel = "final " + error_key;
  if (opt.log) print_run_table(*opt.log, runs);
  const nlohmann::json fastest = fastest_at_targets(opt.integrators, points, false, error_key, opt.targets, opt.log);
  // With a reference run, the same summary for the exact-reference error (time + space error).
  const nlohmann::json fastest_exact =
      reference_dt ? fastest_at_targets(opt.integrators, points, true, exact_key, opt.targets, opt.log) : nlohmann::json(nullptr);
  write_file_atomically(opt.output_dir + "/comparison.csv",
                        "integrator,setting,wall_seconds [s],cpu_seconds [s],rhs_evals [-],steps [-],rejected_steps [-],"
                        "stability_limited_steps [-],implicit_solves [-],krylov_iterations [-],krylov_iterations_per_step [-],"
                        "krylov_iterations_per_solve [-],error [" +
                            (reference_dt ? std::string("-") : error_unit(exact_key)) + "],exact_error [" +
                            (exact ? error_unit(exact_key) : std::string("-")) + "],status\n" + csv.str());
  // Charts unless the config says output.plots: false (the CSV and JSON hold every number).
  const std::string chart_problem = base.output.plots ? draw_chart(chart, opt.output_dir, "comparison") : kPlotsOff;
  // The same against CPU time: on a shared machine other jobs stretch the wall time.
  const std::string cpu_chart_problem = base.output.plots ? draw_chart(cpu_chart, opt.output_dir, "comparison_cpu") : kPlotsOff;
  nlohmann::json j{{"case", base.case_name},
                   {"error", error_key},
                   {"reference_run", reference},
                   {"config_file", base.source},
                   {"runs", runs},
                   {"fastest", fastest},
                   {"fastest_exact_error", fastest_exact},
                   {"chart", chart_problem.empty() ? nlohmann::json("comparison.png") : nlohmann::json(nullptr)},
                   {"cpu_chart", cpu_chart_problem.empty() ? nlohmann::json("comparison_cpu.png") : nlohmann::json(nullptr)}};
  if (!chart_problem.empty()) {
    j["chart_problem"] = chart_problem;
    if (opt.log) *opt.log << "compare: no chart: " << chart_problem << '\n';
  }
  write_file_atomically(opt.output_dir + "/comparison.json", j.dump(2) + "\n");
  return j;
}

}  // namespace sphmol
