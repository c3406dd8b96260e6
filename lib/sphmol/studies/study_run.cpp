#include "sphmol/studies/study_run.hpp"

#include <limits>
#include <sstream>

#include "sphmol/run/run_case.hpp"

namespace sphmol {

StudyRun run_study_case(const Config& config) {
  StudyRun r;
  RunOptions opt;
  opt.write_files = false;
  opt.final_state = &r.final_state;
  r.summary = run_case(config, opt);
  r.blown_up = r.summary.value("status", "completed") == "blown_up";
  const std::string key = r.summary.value("primary_error", "e_rms");
  const auto& fe = r.summary["final_errors"];
  r.error = (!r.blown_up && fe.contains(key)) ? fe[key].get<double>() : std::numeric_limits<double>::infinity();
  return r;
}

std::string fmt(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

}  // namespace sphmol
