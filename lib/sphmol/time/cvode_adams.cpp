#include "sphmol/time/cvode_adams.hpp"

#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "sphmol/config/yaml_reader.hpp"
#include "sphmol/time/blow_up.hpp"
#include "sphmol/time/saved_count.hpp"
#include "sphmol/time/state_vector.hpp"
#include "sphmol/time/step_limit.hpp"

namespace sphmol {

namespace {
void check(int flag, const char* what) {
  if (flag < 0) throw std::runtime_error(std::string("CVODE: ") + what + " failed: " + CVodeGetReturnFlagName(flag));
}
}  // namespace

CvodeAdams::~CvodeAdams() { release(); }

void CvodeAdams::release() {
  if (mem_) CVodeFree(&mem_);
  if (nls_) SUNNonlinSolFree(nls_);
  if (y_) N_VDestroy(y_);
  if (ctx_) SUNContext_Free(&ctx_);
  mem_ = nullptr;
  nls_ = nullptr;
  y_ = nullptr;
  ctx_ = nullptr;
  tstop_set_ = false;
}

void CvodeAdams::restart(OdeSystem& sys, double t, double* y) {
  const IntegratorStats s = stats();
  release();
  initialize(sys, t, y);
  steps_before_ = s.steps;
  rejected_before_ = s.rejected_steps;
}

void CvodeAdams::resize(OdeSystem& sys, double t, double* y) {
  if (!mem_) throw std::logic_error("CvodeAdams::resize before initialize");
  if (t != t_) throw std::logic_error("CvodeAdams::resize: the state is not at the integrator's time");
  if (N_VGetArrayPointer(y_) != y) throw std::logic_error("CvodeAdams::resize: the system did not move the state vector with its share");
  sys_ = &sys;
}

nlohmann::json CvodeAdams::describe() const {
  return {{"name", name()},
          {"method", "Adams-Moulton, fixed-point iteration"},
          {"rtol", opt_.rtol},
          {"atol", opt_.atol},
          {"step", "adaptive, max step = CFL step"}};
}

int CvodeAdams::rhs_callback(double t, N_Vector y, N_Vector ydot, void* self) {
  auto* me = static_cast<CvodeAdams*>(self);
  me->sys_->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
  return 0;
}

void CvodeAdams::initialize(OdeSystem& sys, double t0, double* y) {
  sys_ = &sys;
  t_ = t0;
  if (SUNContext_Create(nullptr, &ctx_) != 0) throw std::runtime_error("SUNContext_Create failed");
  // The N_Vector wraps the caller's storage (no copy): serial, or over processes the system's own.
  y_ = make_state_vector(sys, y, 1, ctx_);
  // One evaluation at t0 primes the CFL limit used for the first step.
  std::vector<double> f(sys.size());
  sys.rhs(t0, y, f.data());

  mem_ = CVodeCreate(CV_ADAMS, ctx_);
  if (!mem_) throw std::runtime_error("CVodeCreate failed");
  check(CVodeInit(mem_, &CvodeAdams::rhs_callback, t0, y_), "Init");
  check(CVodeSetUserData(mem_, this), "SetUserData");
  check(CVodeSStolerances(mem_, opt_.rtol, opt_.atol), "SStolerances");
  nls_ = SUNNonlinSol_FixedPoint(y_, 0, ctx_);
  if (!nls_) throw std::runtime_error("SUNNonlinSol_FixedPoint failed");
  check(CVodeSetNonlinearSolver(mem_, nls_), "SetNonlinearSolver");
  check(CVodeSetMaxNumSteps(mem_, opt_.max_steps), "SetMaxNumSteps");
  const double hmax = sys.stable_step();
  if (std::isfinite(hmax)) {
    check(CVodeSetMaxStep(mem_, hmax), "SetMaxStep");
    check(CVodeSetInitStep(mem_, 0.1 * hmax), "SetInitStep");  // Adams starts at order 1
  }
}

void CvodeAdams::advance(double tout) {
  while (t_ < tout) step_toward(tout);
}

double CvodeAdams::step_toward(double tout) {
  if (t_ >= tout) return t_;
  check_step_limit(name(), stats().steps, opt_.max_steps, t_);
  // CVODE clears its stop time once it is reached; a new target sets it again.
  if (!tstop_set_ || tstop_ != tout) {
    check(CVodeSetStopTime(mem_, tout), "SetStopTime");
    tstop_ = tout;
    tstop_set_ = true;
  }
  double t = t_;
  const int flag = CVode(mem_, tout, y_, &t, CV_ONE_STEP);
  if (flag == CV_ERR_FAILURE || flag == CV_CONV_FAILURE || flag == CV_RHSFUNC_FAIL)
    throw BlowUp(t, -1, std::string("step-size collapse: CVODE ") + CVodeGetReturnFlagName(flag));
  if (flag < 0)
    throw std::runtime_error("CVODE: integration failed at t = " + number_text(t) + " s: " + CVodeGetReturnFlagName(flag));
  double h = 0.0;
  CVodeGetLastStep(mem_, &h);
  after_step(t, N_VGetArrayPointer(y_), h);
  // The CFL limit of the latest evaluation bounds the next step.
  const double hmax = sys_->stable_step();
  if (std::isfinite(hmax) && hmax > 0.0) check(CVodeSetMaxStep(mem_, hmax), "SetMaxStep");
  if (flag == CV_TSTOP_RETURN) {
    t = tout;
    tstop_set_ = false;
  }
  t_ = t;
  return t_;
}

nlohmann::json CvodeAdams::save_state() const {
  const IntegratorStats s = stats();
  return {{"steps", s.steps}, {"rejected_steps", s.rejected_steps}};
}

void CvodeAdams::restore_state(const nlohmann::json& s) {
  steps_before_ = saved_count(s, "steps");
  rejected_before_ = saved_count(s, "rejected_steps");
}

IntegratorStats CvodeAdams::stats() const {
  IntegratorStats s;
  long v = 0, w = 0;
  CVodeGetNumSteps(mem_, &v);
  s.steps = v + steps_before_;
  CVodeGetNumErrTestFails(mem_, &v);
  CVodeGetNumNonlinSolvConvFails(mem_, &w);
  s.rejected_steps = v + w + rejected_before_;
  CVodeGetLastStep(mem_, &s.last_step);
  return s;
}

}  // namespace sphmol
