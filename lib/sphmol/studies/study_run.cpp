#include "sphmol/studies/study_run.hpp"

#include <time.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/run/run_case.hpp"

namespace sphmol {

namespace {
double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
}  // namespace

StudyRun run_study_case(const Config& config) {
  StudyRun r;
  const double cpu0 = process_cpu_seconds();
  RunOptions opt;
  opt.write_files = false;
  opt.final_state = &r.final_state;
  try {
    r.summary = run_case(config, opt);
  } catch (const std::exception& e) {
    // A run that stops with an error mid-way (e.g. smoothing lengths grown past half the periodic
    // width) ends that point of the sweep, not the study: it counts as blown up, with the message.
    r.summary = {{"status", "blown_up"},
                 {"blow_up", {{"cause", std::string("run failed: ") + e.what()}}},
                 {"steps", 0},
                 {"rhs_evals", 0},
                 {"wall_seconds", 0.0},
                 {"particles", {{"fluid", 0}}},
                 {"errors", nlohmann::json::array()},
                 {"final_errors", nlohmann::json::object()}};
  }
  r.cpu_seconds = process_cpu_seconds() - cpu0;
  r.blown_up = r.summary.value("status", "completed") == "blown_up";
  const std::string key = r.summary.value("primary_error", "e_rms");
  const auto& fe = r.summary["final_errors"];
  // A case leaves an error it could not measure null (e.g. no output time after the settling time):
  // that run has no error, and says why, instead of failing the study on a null.
  const bool measured = fe.contains(key) && fe[key].is_number();
  r.error = !r.blown_up && measured ? fe[key].get<double>() : std::numeric_limits<double>::infinity();
  if (!r.blown_up && !measured)
    r.note = "final_errors." + key + " was not measured in this run (see the case's output times and t_end)";
  return r;
}

namespace {
template <int D>
double stable_step_at_start(const Config& config) {
  auto c = make_case<D>(config);
  auto sys = c->build(config);
  std::vector<double> y = sys->initial_state(), ydot(sys->size());
  sys->rhs(0.0, y.data(), ydot.data());  // the CFL limit belongs to the state of the latest evaluation
  return sys->stable_step();
}
}  // namespace

double initial_stable_step(const Config& config) {
  switch (config.dimension) {
    case 1: return stable_step_at_start<1>(config);
    case 2: return stable_step_at_start<2>(config);
    case 3: return stable_step_at_start<3>(config);
    default: throw std::invalid_argument("dimension: must be 1, 2 or 3");
  }
}

namespace {
// Built: whether a reference applies may depend on the scene (the dam break's column shape).
template <int D>
bool built_case_has_exact_reference(const Config& config) {
  auto c = make_case<D>(config);
  c->build(config);
  return c->has_exact_reference();
}
}  // namespace

bool case_has_exact_reference(const Config& config) {
  switch (config.dimension) {
    case 1: return built_case_has_exact_reference<1>(config);
    case 2: return built_case_has_exact_reference<2>(config);
    default: return built_case_has_exact_reference<3>(config);
  }
}

double relative_difference(double value, double reference) {
  if (!std::isfinite(value)) return std::numeric_limits<double>::infinity();
  const double d = std::abs(value - reference);
  return reference != 0.0 ? d / std::abs(reference) : d;
}

double relative_velocity_error(const std::vector<double>& y, const std::vector<double>& yref, int dimension, std::size_t n) {
  // The velocity blocks follow the D position blocks: y = [x_0..x_{D-1} | v_0..v_{D-1} | ...].
  if (y.size() != yref.size() || y.size() < 2 * dimension * n || n == 0) return std::numeric_limits<double>::infinity();
  const std::size_t vb = dimension * n, ve = 2 * dimension * n;
  double sum = 0.0, vmax = 0.0;
  for (std::size_t k = vb; k < ve; ++k) {
    const double d = y[k] - yref[k];
    sum += d * d;
    vmax = std::max(vmax, std::abs(yref[k]));
  }
  const double rms = std::sqrt(sum / static_cast<double>(ve - vb));
  return vmax > 0 ? rms / vmax : rms;
}

double max_abs_velocity(const std::vector<double>& y, int dimension, std::size_t n) {
  const std::size_t vb = dimension * n, ve = 2 * dimension * n;
  if (y.size() < ve) return 0.0;
  double vmax = 0.0;
  for (std::size_t k = vb; k < ve; ++k) vmax = std::max(vmax, std::abs(y[k]));
  return vmax;
}

std::string csv_number(double x) { return std::isfinite(x) ? fmt(x) : std::string(); }

std::string fmt(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

}  // namespace sphmol
