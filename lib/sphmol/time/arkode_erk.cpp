#include "sphmol/time/arkode_erk.hpp"

#include <omp.h>
#include "sphmol/config/yaml_reader.hpp"
#include "sphmol/io/double_codec.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "sphmol/time/blow_up.hpp"
#include "sphmol/time/erk_table.hpp"
#include "sphmol/time/saved_count.hpp"
#include "sphmol/time/state_vector.hpp"
#include "sphmol/time/step_limit.hpp"

namespace sphmol {

namespace {
constexpr double kCflFraction = 0.5;

void check(int flag, const char* what) {
  if (flag < 0) throw std::runtime_error(std::string("ARKODE: ") + what + " failed: " + ERKStepGetReturnFlagName(flag));
}
}  // namespace

ArkodeErk::ArkodeErk(Options o) : opt_(std::move(o)) {}

ArkodeErk::~ArkodeErk() {
  if (mem_) ERKStepFree(&mem_);
  if (y_) N_VDestroy(y_);
  if (ctx_) SUNContext_Free(&ctx_);
}

nlohmann::json ArkodeErk::describe() const {
  nlohmann::json j{{"name", name()}, {"table", opt_.table}};
  if (opt_.fixed_step) {
    j["dt"] = *opt_.fixed_step;
  } else {
    j["rtol"] = opt_.rtol;
    j["atol"] = opt_.atol;
    if (mem_) {
      // Step attempts whose size the CFL limit set, and those the error controller set.
      const auto [exp_steps, acc_steps] = limited_steps();
      j["stability_limited_steps"] = exp_steps;
      j["accuracy_limited_steps"] = acc_steps;
    }
  }
  return j;
}

int ArkodeErk::rhs_callback(double t, N_Vector y, N_Vector ydot, void* self) {
  auto* me = static_cast<ArkodeErk*>(self);
  me->sys_->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
  return 0;
}

int ArkodeErk::stability_callback(N_Vector, double, double* hstab, void* self) {
  // ARKODE multiplies hstab by its CFL fraction (which must be < 1); the time.cfl coefficients already
  // hold the safety margin, so hand it the limit divided by that fraction.
  *hstab = static_cast<ArkodeErk*>(self)->sys_->stable_step() / kCflFraction;
  return 0;
}

void ArkodeErk::initialize(OdeSystem& sys, double t0, double* y) {
  sys_ = &sys;
  t_ = t0;
  if (SUNContext_Create(nullptr, &ctx_) != 0) throw std::runtime_error("SUNContext_Create failed");
  // The N_Vector wraps the caller's storage (no copy): the system's own vector when its state is
  // split over processes (time/state_vector.hpp); else, with several threads, the OpenMP vector
  // runs the integrator's vector operations in parallel as well.
  y_ = make_state_vector(sys, y, omp_get_max_threads(), ctx_);
  // One evaluation at t0 primes the CFL limit used for the first step.
  std::vector<double> f(sys.size());
  sys.rhs(t0, y, f.data());

  mem_ = ERKStepCreate(&ArkodeErk::rhs_callback, t0, y_, ctx_);
  if (!mem_) throw std::runtime_error("ERKStepCreate failed");
  check(ERKStepSetUserData(mem_, this), "SetUserData");
  // The table with a true last stage where ERKStep would reuse a wrong one (time/erk_table.hpp).
  ARKodeButcherTable table = load_erk_table(opt_.table);
  if (!table) throw std::runtime_error("ARKODE: unknown or non-explicit Butcher table '" + opt_.table + "'");
  const int set = ERKStepSetTable(mem_, table);  // ERKStep keeps a copy
  ARKodeButcherTable_Free(table);
  check(set, "SetTable");
  check(ERKStepSetMaxNumSteps(mem_, opt_.max_steps), "SetMaxNumSteps");
  if (opt_.fixed_step) {
    check(ERKStepSetFixedStep(mem_, *opt_.fixed_step), "SetFixedStep");
  } else {
    check(ERKStepSStolerances(mem_, opt_.rtol, opt_.atol), "SStolerances");
    check(ERKStepSetStabilityFn(mem_, &ArkodeErk::stability_callback, this), "SetStabilityFn");
    check(ERKStepSetCFLFraction(mem_, kCflFraction), "SetCFLFraction");
    check(ERKStepSetInitStep(mem_, sys.stable_step()), "SetInitStep");
  }
}

void ArkodeErk::advance(double tout) {
  // One step at a time, so the step hook (blow-up detection) sees every accepted step.
  while (t_ < tout) step_toward(tout);
}

double ArkodeErk::step_toward(double tout) {
  if (t_ >= tout) return t_;
  check_step_limit(name(), stats().steps, opt_.max_steps, t_);
  check(ERKStepSetStopTime(mem_, tout), "SetStopTime");
  double t = t_;
  // One internal step; the stop time keeps it from passing tout (same steps as advance()).
  const int flag = ERKStepEvolve(mem_, tout, y_, &t, ARK_ONE_STEP);
  if (flag == ARK_ERR_FAILURE || flag == ARK_CONV_FAILURE || flag == ARK_RHSFUNC_FAIL)
    throw BlowUp(t, -1, std::string("step-size collapse: ARKODE ") + ERKStepGetReturnFlagName(flag));
  if (flag < 0)
    throw std::runtime_error("ARKODE: integration failed at t = " + number_text(t) + " s: " +
                             ERKStepGetReturnFlagName(flag));
  t_ = (flag == ARK_TSTOP_RETURN) ? tout : t;
  double h = 0.0;
  ERKStepGetLastStep(mem_, &h);
  after_step(t_, N_VGetArrayPointer(y_), h);
  return t_;
}

std::pair<long, long> ArkodeErk::limited_steps() const {
  long exp_steps = 0, acc_steps = 0;
  if (mem_) {
    ERKStepGetNumExpSteps(mem_, &exp_steps);
    ERKStepGetNumAccSteps(mem_, &acc_steps);
  }
  return {exp_steps + stability_limited_before_, acc_steps + accuracy_limited_before_};
}

nlohmann::json ArkodeErk::save_state() const {
  double h = 0.0;
  ERKStepGetCurrentStep(mem_, &h);
  const IntegratorStats s = stats();
  const auto [exp_steps, acc_steps] = limited_steps();
  return {{"step", encode_doubles({h})},
          {"steps", s.steps},
          {"rejected_steps", s.rejected_steps},
          {"stability_limited_steps", exp_steps},
          {"accuracy_limited_steps", acc_steps}};
}

void ArkodeErk::restore_state(const nlohmann::json& s) {
  const double h = decode_doubles(s.at("step").get<std::string>()).at(0);
  if (!opt_.fixed_step && h > 0.0 && std::isfinite(h)) check(ERKStepSetInitStep(mem_, h), "SetInitStep");
  steps_before_ = s.at("steps").get<long>();
  rejected_before_ = s.at("rejected_steps").get<long>();
  stability_limited_before_ = saved_count(s, "stability_limited_steps");
  accuracy_limited_before_ = saved_count(s, "accuracy_limited_steps");
}

void ArkodeErk::resize(OdeSystem& sys, double t, double* y) {
  if (!mem_) throw std::logic_error("ArkodeErk::resize before initialize");
  if (t != t_) throw std::logic_error("ArkodeErk::resize: the state is not at the integrator's time");
  if (N_VGetArrayPointer(y_) != y) throw std::logic_error("ArkodeErk::resize: the system did not move the state vector with its share");
  sys_ = &sys;
}

void ArkodeErk::restart(OdeSystem& sys, double t, double* y) {
  if (!mem_) throw std::logic_error("ArkodeErk::restart before initialize");
  if (t != t_) throw std::logic_error("ArkodeErk::restart: the state is not at the integrator's time");
  sys_ = &sys;
  N_VDestroy(y_);
  y_ = make_state_vector(sys, y, omp_get_max_threads(), ctx_);
  // No resize function: ARKODE clones its vectors from y_ anew; their contents (stages, the last
  // f) are scratch or computed again from (t, y).
  check(ERKStepResize(mem_, y_, 1.0, t, nullptr, nullptr), "Resize");
}

IntegratorStats ArkodeErk::stats() const {
  IntegratorStats s;
  long v = 0;
  ERKStepGetNumSteps(mem_, &v);
  s.steps = v + steps_before_;
  ERKStepGetNumErrTestFails(mem_, &v);
  s.rejected_steps = v + rejected_before_;
  ERKStepGetLastStep(mem_, &s.last_step);
  return s;
}

}  // namespace sphmol
