#include "sphmol/studies/stability.hpp"

#include "sphmol/cases/case_module.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>
#include <vector>

#include "sphmol/io/atomic_file.hpp"
#include "sphmol/run/output_folder.hpp"
#include "sphmol/run/error_unit.hpp"
#include "sphmol/studies/gnuplot_chart.hpp"
#include "sphmol/studies/study_run.hpp"

namespace sphmol {

constexpr double kDivergedSigned = 1.0;

StabilityClass classify_run(const nlohmann::json& summary, double osc_threshold) {
  StabilityClass c;
  if (summary.value("status", "completed") == "blown_up") {
    c.label = "blown_up";
    return c;
  }
  std::vector<double> s;
  for (const auto& m : summary["errors"])
    if (m.contains("e_signed")) s.push_back(m["e_signed"].get<double>());
  // A case without a signed error (Taylor-Green, the cavity, the tanks, scenes) gives nothing to
  // test for oscillation or growth: its run is only known not to have blown up.
  if (s.empty()) {
    c.label = "not_blown_up";
    return c;
  }
  for (double x : s) c.max_abs_signed = std::max(c.max_abs_signed, std::abs(x));
  c.signed_measured = true;
  // An error larger than the velocity scale itself is unbounded growth (a numerical instability
  // that has not yet thrown a particle out), not the bounded oscillation.
  if (c.max_abs_signed > kDivergedSigned) {
    c.label = "blown_up";
    return c;
  }
  // Skip the start-up (first tenth of the samples); count swings of e_signed about its mean over
  // the rest. The oscillation of Vukčević 2012, §9 is about the run's own (slightly biased) level, not
  // about the exact solution, so the sign is taken relative to that mean.
  const std::size_t first = s.size() / 10;
  double mean = 0.0;
  for (std::size_t k = first; k < s.size(); ++k) mean += s[k];
  if (s.size() > first) mean /= static_cast<double>(s.size() - first);
  int last_sign = 0;
  double lo = 0.0, hi = 0.0;
  for (std::size_t k = first; k < s.size(); ++k) {
    const double d = s[k] - mean;
    lo = std::min(lo, d);
    hi = std::max(hi, d);
    if (std::abs(d) <= osc_threshold) continue;  // within the threshold: no sign
    const int sign = d > 0 ? 1 : -1;
    if (last_sign != 0 && sign != last_sign) ++c.sign_changes;
    last_sign = sign;
  }
  c.amplitude = 0.5 * (hi - lo);
  c.swings_measured = true;
  c.label = c.sign_changes >= 2 ? "oscillating" : "stable";
  return c;
}

// Every sound speed of the scene x factor: the case's own rule (e.g. gas states) or fluid.eos.sound_speed.
double scale_sound_speed(Config& c, double factor) {
  const CaseModule* m = find_case_module(c.case_name);
  if (m && m->scale_sound_speed) return m->scale_sound_speed(c, factor);
  c.fluid.eos.sound_speed *= factor;
  return c.fluid.eos.sound_speed;
}

nlohmann::json run_stability(const Config& base, const StabilityOptions& opt) {
  // Every factor's scene is checked before anything runs or is written (ConfigError): a factor the
  // case refuses would otherwise fail halfway through the map.
  for (double fc : opt.sound_speed_factors) {
    Config c = base;
    scale_sound_speed(c, fc);
  }
  // Locked for the study's lifetime: two studies into one folder would overwrite each other's files.
  const OutputFolder folder(opt.output_dir, OutputFolder::Options{.lock_only = true});
  const bool fixed = base.time.dt.has_value();
  std::ostringstream csv;
  std::string error_key;  // the case's error measure, for the unit in the CSV header
  std::map<std::string, ChartSeries> by_class;
  by_class["stable"] = ChartSeries{"stable", {}, {}, "forest-green"};
  by_class["oscillating"] = ChartSeries{"oscillating", {}, {}, "dark-orange"};
  by_class["blown_up"] = ChartSeries{"blown_up", {}, {}, "red"};
  by_class["not_blown_up"] = ChartSeries{"not blown up (no e_signed)", {}, {}, "grey40"};
  nlohmann::json runs = nlohmann::json::array();
  for (double fc : opt.sound_speed_factors)
    for (double fs : opt.step_factors) {
      Config c = base;
      const double sound_speed = scale_sound_speed(c, fc);
      double step_value = fs;
      if (fixed) {
        c.time.dt = *base.time.dt * fs;
        step_value = *c.time.dt;
      } else {
        c.time.cfl.acoustic *= fs;
        c.time.cfl.force *= fs;
        c.time.cfl.viscous *= fs;
      }
      c.output.times.clear();
      for (int k = 1; k <= opt.samples; ++k) c.output.times.push_back(c.time.t_end * k / opt.samples);
      c.output.profiles = false;
      const StudyRun r = run_study_case(c);
      const StabilityClass cl = classify_run(r.summary, opt.osc_threshold);
      error_key = r.summary.value("primary_error", "e_rms");
      const std::string cause = r.blown_up ? r.summary["blow_up"]["cause"].get<std::string>() : std::string();
      std::string cause_csv = cause;
      for (char& ch : cause_csv)
        if (ch == ',' || ch == '"') ch = ';';
      // Not measured (no e_signed, or blown up first): empty cells and nulls, not 0.
      const double nan = std::numeric_limits<double>::quiet_NaN();
      const double swings = cl.swings_measured ? cl.sign_changes : nan, amplitude = cl.swings_measured ? cl.amplitude : nan;
      const double max_signed = cl.signed_measured ? cl.max_abs_signed : nan;
      const auto value = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
      csv << fmt(sound_speed) << ',' << fmt(step_value) << ',' << cl.label << ',' << r.summary["status"].get<std::string>() << ','
          << csv_number(swings) << ',' << csv_number(amplitude) << ',' << csv_number(max_signed) << ',' << csv_number(r.error) << ','
          << r.summary["steps"] << ',' << fmt(r.summary["wall_seconds"].get<double>()) << ',' << cause_csv << '\n';
      runs.push_back({{"sound_speed", sound_speed}, {fixed ? "dt" : "cfl_factor", step_value}, {"class", cl.label},
                      {"sign_changes", cl.swings_measured ? nlohmann::json(cl.sign_changes) : nlohmann::json(nullptr)},
                      {"late_amplitude", value(amplitude)}, {"max_abs_e_signed", value(max_signed)},
                      {"error", r.blown_up ? nlohmann::json(nullptr) : nlohmann::json(r.error)}, {"cause", cause}});
      by_class[cl.label].x.push_back(sound_speed);
      by_class[cl.label].y.push_back(step_value);
      if (opt.log) {
        std::string details;
        if (cl.swings_measured) details = "sign changes " + std::to_string(cl.sign_changes) + ", late amplitude " + fmt(cl.amplitude) + ", ";
        if (cl.signed_measured) details += "max |e_signed| " + fmt(cl.max_abs_signed) + ", ";
        details += cause;
        if (details.size() >= 2 && details.compare(details.size() - 2, 2, ", ") == 0) details.resize(details.size() - 2);
        *opt.log << "stability: c = " << fmt(sound_speed) << (fixed ? ", dt = " : ", cfl factor = ") << fmt(step_value) << ": "
                 << cl.label << (details.empty() ? "" : " (" + details + ")") << (r.note.empty() ? "" : "; " + r.note) << '\n';
      }
    }
  write_file_atomically(opt.output_dir + "/stability.csv",
                        std::string("sound_speed [m/s],") + (fixed ? "dt [s]" : "cfl_factor [-]") +
                            ",class,status,sign_changes [-],late_amplitude [-],max_abs_e_signed [-],error [" +
                            error_unit(error_key) + "],steps [-],wall_seconds [s],cause\n" + csv.str());
  Chart chart{"stability map: " + base.case_name, "sound speed c [m/s]", fixed ? "dt [s]" : "CFL factor", true, true, {}, "points pointsize 2"};
  chart.tight = true;
  // A log axis within one decade gets no tick labels: an axis is linear unless it spans one.
  const auto spans_decade = [&](std::vector<double> ChartSeries::*axis) {
    double lo = 0.0, hi = 0.0;
    for (const auto& [label, series] : by_class)
      for (double v : series.*axis) {
        lo = lo > 0.0 ? std::min(lo, v) : v;
        hi = std::max(hi, v);
      }
    return lo > 0.0 && hi / lo >= 10.0;
  };
  chart.logx = spans_decade(&ChartSeries::x);
  chart.logy = spans_decade(&ChartSeries::y);
  for (const char* k : {"stable", "oscillating", "not_blown_up", "blown_up"})
    if (!by_class[k].x.empty()) chart.series.push_back(by_class[k]);
  const std::string problem = base.output.plots ? draw_chart(chart, opt.output_dir, "stability") : kPlotsOff;
  nlohmann::json j{{"case", base.case_name}, {"step_mode", fixed ? "fixed dt" : "cfl factor"}, {"osc_threshold", opt.osc_threshold},
                   {"samples", opt.samples}, {"runs", runs}};
  j["chart"] = problem.empty() ? nlohmann::json("stability.png") : nlohmann::json(nullptr);
  if (!problem.empty()) j["chart_problem"] = problem;
  write_file_atomically(opt.output_dir + "/stability.json", j.dump(2) + "\n");
  return j;
}

}  // namespace sphmol
