#include "sphmol/studies/converge.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <utility>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "sphmol/core/least_squares.hpp"
#include "sphmol/io/atomic_file.hpp"
#include "sphmol/run/output_folder.hpp"
#include "sphmol/run/error_unit.hpp"
#include "sphmol/studies/gnuplot_chart.hpp"
#include "sphmol/studies/study_run.hpp"

namespace sphmol {

namespace {
constexpr int kReferenceRefinement = 8;
// arkode_imex solves its implicit stages to a tolerance from time.rtol and time.atol, also at a fixed
// step; at the defaults (1e-6, 1e-12) that error (near 1e-8 relative) hides the step's. The time
// study solves them to rtol 1e-14 and atol 1e-14 max|v_ref| (an absolute atol far below the flow's
// velocities would ask for more than round-off where the fluid starts at rest).
constexpr double kImexStudyTolerance = 1e-14;

// The longest run of consecutive clean levels (the finer one of equal runs): [first, last], or
// first == last when no two consecutive levels are clean.
std::pair<int, int> clean_run(const std::vector<bool>& clean) {
  int best_first = 0, best_last = 0, first = -1;
  for (int k = 0; k < static_cast<int>(clean.size()); ++k) {
    if (!clean[k]) {
      first = -1;
      continue;
    }
    if (first < 0) first = k;
    if (k - first >= best_last - best_first) best_first = first, best_last = k;
  }
  return {best_first, best_last};
}

}  // namespace

std::vector<IntegratorSpec> default_time_integrators() {
  return parse_integrator_list(
      "leapfrog,leapfrog_kdk,arkode_erk:ARKODE_HEUN_EULER_2_1_2,arkode_erk:ARKODE_BOGACKI_SHAMPINE_4_2_3,"
      "arkode_erk:ARKODE_ZONNEVELD_5_3_4",
      "ARKODE_DORMAND_PRINCE_7_4_5");
}

std::vector<double> pairwise_orders(const std::vector<double>& e) {
  std::vector<double> p;
  for (std::size_t k = 0; k + 1 < e.size(); ++k) p.push_back(std::log(e[k] / e[k + 1]) / std::log(2.0));
  return p;
}

double least_squares_order(const std::vector<double>& e) {
  // log e = a + p log(step), step_k = step_0 / 2^k  ->  slope against x_k = -k log 2.
  std::vector<double> x(e.size()), y(e.size());
  for (std::size_t k = 0; k < e.size(); ++k) x[k] = -static_cast<double>(k) * std::log(2.0), y[k] = std::log(e[k]);
  return least_squares_slope(x, y);
}

nlohmann::json run_converge(const Config& base, const ConvergeOptions& opt) {
  if (opt.levels < 2) throw std::invalid_argument("--levels must be at least 2");
  if (opt.refine != "time" && opt.refine != "space") throw std::invalid_argument("--refine must be time or space");
  // Locked for the study's lifetime: two studies into one folder would overwrite each other's files.
  const OutputFolder folder(opt.output_dir, OutputFolder::Options{.lock_only = true});
  const bool time = opt.refine == "time";
  Config cfg = base;
  cfg.output.times = {cfg.time.t_end};  // only t_end: the fixed steps land on it exactly
  cfg.output.profiles = false;

  std::vector<IntegratorSpec> specs = opt.integrators;
  if (specs.empty() && time) specs = default_time_integrators();
  if (specs.empty()) {
    // Space refinement honours the configured integrator and its accuracy settings.
    IntegratorSpec s;
    s.integrator = base.time.integrator;
    s.table = base.time.integrator == "arkode_erk" ? base.time.table : std::string();
    s.label = s.table.empty() ? s.integrator : s.integrator + ":" + s.table;
    specs.push_back(s);
  }

  nlohmann::json levels = nlohmann::json::array();
  nlohmann::json series = nlohmann::json::array();
  std::ostringstream csv;
  Chart chart{std::string("convergence in ") + (time ? "time" : "space") + ": " + base.case_name,
              time ? "dt [s]" : "particle spacing dx [m]", time ? "rel. rms velocity error vs reference run" : "error vs analytic", true,
              true, {}};

  std::vector<double> ref_state;
  double ref_vmax = 0.0;
  std::string series_error_key = "e_rms";  // the case's primary error, from the first summary
  double dt0 = 0.0;
  bool uneven_steps = false;  // dt0 does not divide t_end or an output time
  if (time) {
    if (opt.dt0) dt0 = *opt.dt0;
    else if (base.time.dt) dt0 = *base.time.dt;
    else dt0 = initial_stable_step(cfg);  // the case's CFL step at t = 0 (time.cfl)
    if (!(dt0 > 0.0 && std::isfinite(dt0)))
      throw std::invalid_argument("--refine time: no usable coarsest step (" + fmt(dt0) + " s); give --dt0");
    if (dt0 > cfg.time.t_end)
      throw std::invalid_argument("--refine time: the coarsest step " + fmt(dt0) + " s is longer than time.t_end = " +
                                  fmt(cfg.time.t_end) + " s; give a smaller --dt0");
    if (!opt.dt0 && !base.time.dt) {
      // The CFL step, shortened to divide t_end into whole steps (see below).
      const double cfl = dt0, n = std::ceil(cfg.time.t_end / cfl * (1.0 - 1e-12));
      dt0 = cfg.time.t_end / n;
      if (opt.log)
        *opt.log << "converge: coarsest step dt0 = " << fmt(dt0) << " s (the CFL step at t = 0, " << fmt(cfl) << " s, shortened to divide t_end into "
                 << fmt(n) << " steps)\n";
    }
    // A fixed step that does not divide t_end (or an output time, where the run stops too) leaves a
    // shorter step there, whose share of the error differs from level to level: the observed order scatters.
    {
      std::vector<double> stops = cfg.output.times;
      stops.push_back(cfg.time.t_end);
      for (const double t : stops) {
        const double n = t / dt0;
        if (std::abs(n - std::round(n)) > 1e-9 * std::max(1.0, n)) {
          uneven_steps = true;
          if (opt.log)
            *opt.log << "converge: warning: dt0 = " << fmt(dt0) << " s does not divide t = " << fmt(t) << " s (" << fmt(n)
                     << " steps): each level ends that interval with a shorter step and the observed order may scatter; "
                     << "give --dt0 = " << fmt(t / std::ceil(n)) << " s or another divisor\n";
          break;
        }
      }
    }
    const double dt_fine = dt0 / std::pow(2.0, opt.levels - 1);
    for (int k = 0; k < opt.levels; ++k) levels.push_back({{"level", k}, {"dt", dt0 / std::pow(2.0, k)}});
    Config rc = cfg;
    rc.time.integrator = "arkode_erk";
    rc.time.table = kReferenceTable;
    rc.time.dt = dt_fine / kReferenceRefinement;
    const StudyRun ref = run_study_case(rc);
    if (ref.blown_up) throw std::runtime_error("the reference run blew up: " + ref.summary["blow_up"].dump());
    ref_state = ref.final_state;
    ref_vmax = max_abs_velocity(ref_state, base.dimension, ref.summary["particles"]["fluid"].get<std::size_t>());
    if (opt.log)
      *opt.log << "converge: reference " << kReferenceTable << " dt = " << fmt(*rc.time.dt) << " (" << fmt(ref.summary["wall_seconds"].get<double>())
               << " s)\n";
  } else {
    const int n0 = base.discretization.particles_across;
    const double dx0 = base.discretization.spacing;
    if (n0 <= 0 && !(dx0 > 0.0)) throw std::invalid_argument("--refine space needs discretization.particles_across or discretization.spacing");
    if (n0 > 0 && (static_cast<long long>(n0) << (opt.levels - 1)) > 1'000'000'000LL)
      throw std::invalid_argument("--refine space: particles_across " + std::to_string(n0) + " x 2^" +
                                  std::to_string(opt.levels - 1) + " is too many");
    for (int k = 0; k < opt.levels; ++k)
      levels.push_back(n0 > 0 ? nlohmann::json{{"level", k}, {"particles_across", n0 << k}}
                              : nlohmann::json{{"level", k}, {"spacing", dx0 / std::pow(2.0, k)}});
  }

  // A case without an exact reference (a user scene) has a quantity as its primary error: in space,
  // each level is measured against one more level at half the finest spacing.
  const bool quantity = !time && !case_has_exact_reference(base);
  if (quantity && opt.log)
    *opt.log << "converge: case '" << base.case_name << "' has no exact reference; each level's primary quantity is compared with a "
             << "reference run at half the finest spacing\n";
  for (const auto& spec : specs) {
    if (time && spec.adaptive() && spec.integrator == "cvode_adams")
      throw std::invalid_argument("--refine time: cvode_adams has no fixed step");
    std::vector<double> errors, dts, walls;
    std::vector<std::string> statuses;
    // arkode_imex at fixed steps: its stage solves' tolerance, relative to max|v_ref| as the error is
    // (0: no stage solves). A level whose error is below it may be measuring the solves, not the step.
    double solve_tolerance = 0.0;
    std::optional<double> study_rtol, study_atol;
    if (time && spec.integrator == "arkode_imex") {
      if (!base.time.rtol_given) study_rtol = kImexStudyTolerance;
      if (!base.time.atol_given && ref_vmax > 0.0) study_atol = kImexStudyTolerance * ref_vmax;
      const double rtol = study_rtol.value_or(cfg.time.rtol), atol = study_atol.value_or(cfg.time.atol);
      solve_tolerance = rtol + (ref_vmax > 0.0 ? atol / ref_vmax : 0.0);
      if (opt.log)
        *opt.log << "converge: " << spec.label << ": stage solves at time.rtol = " << fmt(rtol) << (study_rtol ? "" : " (given)")
                 << ", time.atol = " << fmt(atol) << (study_atol ? "" : " (given)") << '\n';
    }
    const int runs = quantity ? opt.levels + 1 : opt.levels;
    for (int k = 0; k < runs; ++k) {
      Config c = cfg;
      spec.apply(c.time);
      if (study_rtol) c.time.rtol = *study_rtol;
      if (study_atol) c.time.atol = *study_atol;
      double xk;
      if (time) {
        c.time.dt = dt0 / std::pow(2.0, k);
        xk = *c.time.dt;
      } else {
        const double refine = std::pow(2.0, k);
        if (base.discretization.particles_across > 0) {
          c.discretization.particles_across = base.discretization.particles_across << k;
          c.discretization.spacing = 0.0;
        } else {
          c.discretization.spacing = base.discretization.spacing / refine;
        }
        // A fixed step shrinks with dx (constant Courant number), as CFL steps do by themselves.
        if (base.time.dt) c.time.dt = *base.time.dt / refine;
        xk = 0.0;
      }
      const StudyRun r = run_study_case(c);
      if (r.summary.contains("primary_error")) series_error_key = r.summary["primary_error"].get<std::string>();
      if (!time) {
        // The spacing the scene actually used (particles_across is turned into one by the scene).
        const auto& d = r.summary.value("discretization", nlohmann::json::object());
        // Every case reports the spacing its scene used (Case::annotate); a run that ended before
        // the summary has none, and its level is plotted at the configured spacing if there is one.
        xk = d.contains("spacing") && d["spacing"].is_number() ? d["spacing"].get<double>()
             : c.discretization.spacing > 0.0                  ? c.discretization.spacing
                                                              : std::numeric_limits<double>::quiet_NaN();
      }
      if (opt.log && !r.note.empty()) *opt.log << "converge: " << spec.label << " level " << k << ": " << r.note << '\n';
      const double e = time ? (r.blown_up ? std::numeric_limits<double>::infinity() : relative_velocity_error(r.final_state, ref_state, base.dimension, r.summary["particles"]["fluid"].get<std::size_t>()))
                            : r.error;
      errors.push_back(e);
      dts.push_back(xk);
      walls.push_back(r.summary["wall_seconds"].get<double>());
      statuses.push_back(r.blown_up ? "blown_up" : "completed");
      if (opt.log)
        *opt.log << "converge: " << spec.label << (k == opt.levels ? " reference level " : " level ") << k << " (" << fmt(xk)
                 << "): "
                 << (r.blown_up           ? std::string("blown up")
                     : std::isfinite(e)   ? (quantity ? series_error_key + " " : "error ") + fmt(e)
                                          : (quantity ? series_error_key : std::string("error")) + " not measured")
                 << '\n';
    }
    if (quantity) {
      const double ref = errors.back();
      errors.pop_back();
      dts.pop_back();
      walls.pop_back();
      statuses.pop_back();
      for (double& e : errors) e = relative_difference(e, ref);
    }
    // Clean levels: completed with a finite error > 0, not below the stage solves' tolerance. Orders
    // are taken between consecutive clean levels only; the overall order over the longest run of them.
    std::vector<bool> clean(opt.levels), below_solves(opt.levels, false);
    for (int k = 0; k < opt.levels; ++k) {
      below_solves[k] = statuses[k] == "completed" && std::isfinite(errors[k]) && errors[k] < solve_tolerance;
      clean[k] = statuses[k] == "completed" && std::isfinite(errors[k]) && errors[k] > 0.0 && !below_solves[k];
      if (below_solves[k] && opt.log)
        *opt.log << "converge: " << spec.label << " level " << k << ": error " << fmt(errors[k])
                 << " is below the stage solves' tolerance " << fmt(solve_tolerance)
                 << " (time.rtol + time.atol / max|v_ref|): it may be theirs, not the step's; left out of the order"
                 << (base.time.rtol_given || base.time.atol_given ? " (a smaller time.rtol / time.atol, or leave them unset)" : "")
                 << '\n';
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> orders = pairwise_orders(errors);
    for (int k = 0; k + 1 < opt.levels; ++k)
      if (!clean[k] || !clean[k + 1]) orders[k] = nan;
    const auto [first, last] = clean_run(clean);
    const double slope =
        last > first ? least_squares_order(std::vector<double>(errors.begin() + first, errors.begin() + last + 1)) : nan;
    const int expected = time ? spec.order() : 0;
    for (int k = 0; k < opt.levels; ++k)
      csv << opt.refine << ',' << spec.label << ',' << k << ',' << fmt(dts[k]) << ',' << csv_number(errors[k]) << ','
          << (k > 0 ? csv_number(orders[k - 1]) : std::string()) << ',' << (expected > 0 ? std::to_string(expected) : std::string())
          << ',' << fmt(walls[k]) << ',' << statuses[k] << '\n';
    const auto numbers = [](const std::vector<double>& v) {
      nlohmann::json a = nlohmann::json::array();
      for (double x : v) a.push_back(std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr));
      return a;
    };
    nlohmann::json s{{"integrator", spec.label},
                     {"errors", numbers(errors)},
                     {time ? "steps" : "spacings", dts},
                     {"status", statuses},
                     {"observed_orders", numbers(orders)},
                     {"observed_order", std::isfinite(slope) ? nlohmann::json(slope) : nlohmann::json(nullptr)},
                     {"order_levels", last > first ? nlohmann::json{first, last} : nlohmann::json(nullptr)},
                     {"wall_seconds", walls}};
    s["expected_order"] = expected > 0 ? nlohmann::json(expected) : nlohmann::json(nullptr);
    if (solve_tolerance > 0.0) {
      s["stage_solves"] = {{"rtol", study_rtol.value_or(cfg.time.rtol)},
                           {"atol", study_atol.value_or(cfg.time.atol)},
                           {"relative_tolerance", solve_tolerance},
                           {"below_tolerance", below_solves}};
    }
    series.push_back(s);
    chart.series.push_back({spec.label + " (slope " + (std::isfinite(slope) ? fmt(slope) : std::string("-")) + ")", dts, errors});
    if (opt.log) {
      *opt.log << "converge: " << spec.label << ": observed order ";
      if (last > first)
        *opt.log << fmt(slope) << " (levels " << first << "-" << last << ")";
      else
        *opt.log << "not measured (no two consecutive clean levels)";
      *opt.log << (expected > 0 ? ", expected " + std::to_string(expected) : std::string()) << "\n";
    }
  }
  if (!time) chart.ylabel = quantity ? "relative difference of " + series_error_key + " from the finest run" : "final " + series_error_key;
  write_file_atomically(opt.output_dir + "/convergence.csv",
                        std::string("refine,integrator,level [-],") + (time ? "dt [s]" : "dx [m]") + ",error [" +
                            (time || quantity ? std::string("-") : error_unit(series_error_key)) +
                            "],observed_order [-],expected_order [-],wall_seconds [s],status\n" + csv.str());
  const std::string problem = base.output.plots ? draw_chart(chart, opt.output_dir, "convergence") : kPlotsOff;
  nlohmann::json j{{"refine", opt.refine}, {"case", base.case_name}, {"levels", levels}, {"series", series}};
  if (time) j["uniform_steps"] = !uneven_steps;
  j["error_measure"] = time ? "rms over all fluid velocity components at t_end of (v - v_ref) / max|v_ref|; reference: " +
                                  std::string(kReferenceTable) + " at dt_finest/" + std::to_string(kReferenceRefinement)
                  : quantity ? "|q - q_ref| / |q_ref| of the case's primary quantity " + series_error_key +
                                   ", q_ref from a run at half the finest spacing"
                             : "the case's primary final error " + series_error_key + " against its reference";
  j["chart"] = problem.empty() ? nlohmann::json("convergence.png") : nlohmann::json(nullptr);
  if (!problem.empty()) j["chart_problem"] = problem;
  write_file_atomically(opt.output_dir + "/convergence.json", j.dump(2) + "\n");
  return j;
}

}  // namespace sphmol
