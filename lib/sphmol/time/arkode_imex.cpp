#include "sphmol/time/arkode_imex.hpp"

#include <arkode/arkode_butcher_dirk.h>
#include <arkode/arkode_butcher_erk.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "sphmol/config/yaml_reader.hpp"
#include "sphmol/io/double_codec.hpp"
#include "sphmol/time/block_error_weights.hpp"
#include "sphmol/time/blow_up.hpp"
#include "sphmol/time/saved_count.hpp"
#include "sphmol/time/state_vector.hpp"
#include "sphmol/time/step_limit.hpp"

namespace sphmol {

namespace {
constexpr double kCflFraction = 0.5;

void check(int flag, const char* what) {
  if (flag < 0) throw std::runtime_error(std::string("ARKODE: ") + what + " failed: " + ARKStepGetReturnFlagName(flag));
}
}  // namespace

ArkodeImex::ArkodeImex(Options o) : opt_(std::move(o)) {}

ArkodeImex::~ArkodeImex() { release(); }

void ArkodeImex::release() {
  if (mem_) ARKStepFree(&mem_);
  ls_.reset();
  if (y_) N_VDestroy(y_);
  if (ctx_) SUNContext_Free(&ctx_);
  mem_ = nullptr;
  y_ = nullptr;
  ctx_ = nullptr;
}

void ArkodeImex::restart(OdeSystem& sys, double t, double* y) {
  const Counts c = counts();
  release();
  initialize(sys, t, y);
  before_ = c;
}

nlohmann::json ArkodeImex::describe() const {
  const auto pair = ark_pair_of(opt_.table);
  nlohmann::json j{{"name", name()}, {"table", opt_.table}};
  if (pair) j["tables"] = {{"explicit", pair->erk}, {"implicit", pair->dirk}};
  if (opt_.fixed_step) {
    j["dt"] = *opt_.fixed_step;
  } else {
    j["rtol"] = opt_.rtol;
    j["atol"] = opt_.atol;
  }
  j["krylov"] = {{"solver", opt_.krylov.solver}, {"max_iterations", opt_.krylov.max_iterations}};
  if (mem_) {
    const Counts c = counts();
    const long its = c.krylov, steps = c.steps, newton = c.stage_solves;
    j["krylov_iterations"] = its;
    j["krylov_iterations_per_step"] = steps > 0 ? static_cast<double>(its) / static_cast<double>(steps) : 0.0;
    j["stage_solves"] = newton;
    // SetLinear: one Newton iteration, so one Krylov solve, per implicit stage.
    j["implicit_solves"] = newton;
    j["krylov_iterations_per_solve"] = newton > 0 ? static_cast<double>(its) / static_cast<double>(newton) : 0.0;
    // Step attempts whose size the stability limit (the explicit part's CFL step) set, and those
    // the error controller set (ARKStepGetNumExpSteps / GetNumAccSteps).
    if (!opt_.fixed_step) {
      j["stability_limited_steps"] = c.stability_limited;
      j["accuracy_limited_steps"] = c.accuracy_limited;
    }
  }
  return j;
}

ArkodeImex::Counts ArkodeImex::counts() const {
  Counts c;
  if (mem_) {
    ARKStepGetNumSteps(mem_, &c.steps);
    ARKStepGetNumErrTestFails(mem_, &c.rejected);
    ARKStepGetNumNonlinSolvIters(mem_, &c.stage_solves);
    ARKStepGetNumLinIters(mem_, &c.krylov);
    ARKStepGetNumExpSteps(mem_, &c.stability_limited);
    ARKStepGetNumAccSteps(mem_, &c.accuracy_limited);
  }
  c.steps += before_.steps;
  c.rejected += before_.rejected;
  c.stage_solves += before_.stage_solves;
  c.krylov += before_.krylov;
  c.stability_limited += before_.stability_limited;
  c.accuracy_limited += before_.accuracy_limited;
  return c;
}

void ArkodeImex::evaluate(double t, const double* y) {
  const std::size_t n = sys_->size();
  // Over ranks every rank must take the same branch: the evaluation is collective.
  if (imex_->everywhere(cached_ && t == cache_t_ && std::memcmp(y, cache_y_.data(), n * sizeof(double)) == 0)) return;
  cache_y_.assign(y, y + n);
  cache_t_ = t;
  cached_ = false;
  cache_frozen_ = false;
  imex_->rhs_explicit(t, y, cache_fe_.data(), scratch_);
  scratch_.apply_affine(y + vb_, cache_w_.data());
  cached_ = true;
}

int ArkodeImex::fe_callback(double t, N_Vector y, N_Vector ydot, void* self) {
  auto* me = static_cast<ArkodeImex*>(self);
  const double* yy = N_VGetArrayPointer(y);
  double* f = N_VGetArrayPointer(ydot);
  me->evaluate(t, yy);
  const std::size_t n = me->sys_->size(), vb = me->vb_, nv = me->nv_;
  std::copy(me->cache_fe_.begin(), me->cache_fe_.begin() + static_cast<std::ptrdiff_t>(n), f);
  // At a step's start L_n is the cached evaluation's own operator: the difference below is exactly 0.
  if (me->cache_frozen_) return 0;
  // f_E = f - (L_n v + b_n) = f_E,unfrozen + (L(x) v + b(x)) - (L_n v + b_n)
  me->frozen_.apply_affine(yy + vb, me->wn_.data());
  const double* w = me->cache_w_.data();
  const double* wn = me->wn_.data();
  for (std::size_t k = 0; k < nv; ++k) f[vb + k] += w[k] - wn[k];
  return 0;
}

int ArkodeImex::fi_callback(double, N_Vector y, N_Vector ydot, void* self) {
  auto* me = static_cast<ArkodeImex*>(self);
  const double* yy = N_VGetArrayPointer(y);
  double* f = N_VGetArrayPointer(ydot);
  std::fill(f, f + me->sys_->size(), 0.0);
  me->frozen_.apply_affine(yy + me->vb_, f + me->vb_);
  return 0;
}

int ArkodeImex::weights_callback(N_Vector y, N_Vector w, void* self) {
  auto* me = static_cast<ArkodeImex*>(self);
  const StateBlocks blocks{me->sys_->size(), me->vb_, me->vb_ + me->nv_, me->sys_->block_length()};
  block_error_weights(blocks, me->opt_.rtol, me->opt_.atol, N_VGetArrayPointer(y), N_VGetArrayPointer(w),
                      [me](double* v, std::size_t count) { me->imex_->minimum_everywhere(v, count); });
  return 0;
}

int ArkodeImex::stability_callback(N_Vector, double, double* hstab, void* self) {
  // The limit of the latest evaluation: explicit part only (ImexSystem::rhs_explicit).
  *hstab = static_cast<ArkodeImex*>(self)->sys_->stable_step() / kCflFraction;
  return 0;
}

int ArkodeImex::step_done_callback(double t, N_Vector y, void* self) {
  // L_{n+1}, b_{n+1} at the accepted state; the next step's first stage finds this evaluation cached.
  auto* me = static_cast<ArkodeImex*>(self);
  try {
    me->evaluate(t, N_VGetArrayPointer(y));
  } catch (...) {
    return -1;
  }
  std::swap(me->frozen_, me->scratch_);
  // The cache's W was computed with the operator now frozen: still valid for this state.
  me->cache_frozen_ = true;
  return 0;
}

void ArkodeImex::bind(OdeSystem& sys, double t, const double* y) {
  sys_ = &sys;
  imex_ = dynamic_cast<ImexSystem*>(&sys);
  if (!imex_) throw std::invalid_argument("time.integrator: arkode_imex needs a system with an implicit-explicit split");
  vb_ = sys.velocities_begin();
  nv_ = sys.velocities_end() - vb_;
  const std::size_t n = sys.size();
  cache_fe_.assign(n, 0.0);
  cache_w_.assign(nv_, 0.0);
  wn_.assign(nv_, 0.0);
  cached_ = false;
  evaluate(t, y);  // primes the CFL limit and records the operator of the step starting at (t, y)
  std::swap(frozen_, scratch_);
  cache_frozen_ = true;
  if (frozen_.size() != nv_) throw std::logic_error("arkode_imex: the implicit operator does not match the velocity block");
}

void ArkodeImex::initialize(OdeSystem& sys, double t0, double* y) {
  imex_ = dynamic_cast<ImexSystem*>(&sys);
  if (!imex_) throw std::invalid_argument("time.integrator: arkode_imex needs a system with an implicit-explicit split");
  if (imex_->implicit_terms().empty())
    throw std::invalid_argument("time.integrator: arkode_imex needs an implicit (viscous) term; the scene has none");
  const auto pair = ark_pair_of(opt_.table);
  if (!pair) throw std::invalid_argument("time.table: '" + opt_.table + "' is not one table of an ARK ImEx pair");
  t_ = t0;
  bind(sys, t0, y);

  if (SUNContext_Create(nullptr, &ctx_) != 0) throw std::runtime_error("SUNContext_Create failed");
  // Order-independent norms (time/state_vector.hpp): the same steps on any thread or rank count.
  y_ = make_state_vector(sys, y, omp_get_max_threads(), ctx_);
  mem_ = ARKStepCreate(&ArkodeImex::fe_callback, &ArkodeImex::fi_callback, t0, y_, ctx_);
  if (!mem_) throw std::runtime_error("ARKStepCreate failed");
  check(ARKStepSetUserData(mem_, this), "SetUserData");
  ARKodeButcherTable Be = ARKodeButcherTable_LoadERKByName(pair->erk.c_str());
  ARKodeButcherTable Bi = ARKodeButcherTable_LoadDIRKByName(pair->dirk.c_str());
  if (!Be || !Bi) {
    if (Be) ARKodeButcherTable_Free(Be);
    if (Bi) ARKodeButcherTable_Free(Bi);
    throw std::runtime_error("ARKODE: cannot load the tables of '" + opt_.table + "'");
  }
  const int set = ARKStepSetTables(mem_, Be->q, Be->p, Bi, Be);  // ARKStep keeps copies
  ARKodeButcherTable_Free(Be);
  ARKodeButcherTable_Free(Bi);
  check(set, "SetTables");
  // Lagrange interpolation needs no f at step ends: every stage is evaluated, none is taken from
  // a previous step's last stage (whose split, L_n, is not the next step's).
  check(ARKStepSetInterpolantType(mem_, ARK_INTERP_LAGRANGE), "SetInterpolantType");
  check(ARKStepSetMaxNumSteps(mem_, opt_.max_steps), "SetMaxNumSteps");
  // Error weights with the blocks' own scales (time/block_error_weights.hpp); the stage solves' tolerance
  // derives from them in fixed-step runs too.
  check(ARKStepWFtolerances(mem_, &ArkodeImex::weights_callback), "WFtolerances");
  if (opt_.fixed_step) {
    check(ARKStepSetFixedStep(mem_, *opt_.fixed_step), "SetFixedStep");
  } else {
    check(ARKStepSetStabilityFn(mem_, &ArkodeImex::stability_callback, this), "SetStabilityFn");
    check(ARKStepSetCFLFraction(mem_, kCflFraction), "SetCFLFraction");
    check(ARKStepSetInitStep(mem_, sys.stable_step()), "SetInitStep");
  }
  ls_ = std::make_unique<StageLinearSolver>(ctx_, opt_.krylov, &frozen_, vb_, sys.size());
  ls_->set_gamma([this] {
    double gamma = 0.0;
    check(ARKStepGetCurrentGamma(mem_, &gamma), "GetCurrentGamma");
    return gamma;
  });
  check(ARKStepSetLinearSolver(mem_, ls_->get(), nullptr), "SetLinearSolver");
  check(ARKStepSetLinear(mem_, 1), "SetLinear");  // L_n changes from step to step
  check(ARKStepSetPostprocessStepFn(mem_, &ArkodeImex::step_done_callback), "SetPostprocessStepFn");
  // Stage solves: the maximum-order predictor (method 1) starts Newton near the stage value, a linear
  // tolerance of 0.2 x the nonlinear one (eplifac) suffices for a linear f_I, and f_I at the solved
  // stage is deduced from the solve instead of a further operator product. Poiseuille 80 across to
  // t = 0.2 s at rtol 1e-4: 52 -> 34 Krylov iterations per step, 1.48x less wall time, e_rms equal
  // to 4e-6 relative (docs/performance.md).
  check(ARKStepSetPredictorMethod(mem_, 1), "SetPredictorMethod");
  check(ARKStepSetEpsLin(mem_, 0.2), "SetEpsLin");
  check(ARKStepSetDeduceImplicitRhs(mem_, 1), "SetDeduceImplicitRhs");
}

void ArkodeImex::resize(OdeSystem& sys, double t, double* y) {
  if (!mem_) throw std::logic_error("ArkodeImex::resize before initialize");
  if (t != t_) throw std::logic_error("ArkodeImex::resize: the state is not at the integrator's time");
  if (N_VGetArrayPointer(y_) != y) throw std::logic_error("ArkodeImex::resize: the system did not move the state vector with its share");
  // Between steps y is y_n, at which step_done_callback (or initialize) recorded L_n, b_n and left
  // that evaluation cached: recorded again here over the new share, the same rows with the same
  // entries (parallel/distributed_system.hpp).
  bind(sys, t, y);
  ls_->set_block(vb_, sys.size());
}

void ArkodeImex::advance(double tout) {
  while (t_ < tout) step_toward(tout);
}

double ArkodeImex::step_toward(double tout) {
  if (t_ >= tout) return t_;
  check_step_limit(name(), stats().steps, opt_.max_steps, t_);
  check(ARKStepSetStopTime(mem_, tout), "SetStopTime");
  double t = t_;
  const int flag = ARKStepEvolve(mem_, tout, y_, &t, ARK_ONE_STEP);
  // A solve that threw (out of memory, say) is that failure, not a blow-up.
  if (flag < 0 && ls_->error()) std::rethrow_exception(ls_->error());
  if (flag == ARK_CONV_FAILURE && ls_->last_capped())
    throw std::runtime_error("arkode_imex: at t = " + number_text(t) + " s the stage solves did not reach their tolerance in " +
                             "time.krylov.max_iterations = " + std::to_string(opt_.krylov.max_iterations) + " iterations" +
                             (opt_.fixed_step ? " at the fixed step time.dt" : " even at reduced steps") +
                             " (raise time.krylov.max_iterations" + (opt_.fixed_step ? ", or remove time.dt" : "") + ")");
  if (flag == ARK_ERR_FAILURE || flag == ARK_CONV_FAILURE || flag == ARK_RHSFUNC_FAIL || flag == ARK_LSOLVE_FAIL)
    throw BlowUp(t, -1, std::string("step-size collapse: ARKODE ") + ARKStepGetReturnFlagName(flag));
  if (flag < 0)
    throw std::runtime_error("ARKODE: integration failed at t = " + number_text(t) + " s: " + ARKStepGetReturnFlagName(flag));
  t_ = (flag == ARK_TSTOP_RETURN) ? tout : t;
  double h = 0.0;
  ARKStepGetLastStep(mem_, &h);
  after_step(t_, N_VGetArrayPointer(y_), h);
  return t_;
}

nlohmann::json ArkodeImex::save_state() const {
  double h = 0.0;
  ARKStepGetCurrentStep(mem_, &h);
  const Counts c = counts();
  return {{"step", encode_doubles({h})},
          {"steps", c.steps},
          {"rejected_steps", c.rejected},
          {"stage_solves", c.stage_solves},
          {"krylov_iterations", c.krylov},
          {"stability_limited_steps", c.stability_limited},
          {"accuracy_limited_steps", c.accuracy_limited}};
}

void ArkodeImex::restore_state(const nlohmann::json& s) {
  const double h = decode_doubles(s.at("step").get<std::string>()).at(0);
  if (!opt_.fixed_step && h > 0.0 && std::isfinite(h)) check(ARKStepSetInitStep(mem_, h), "SetInitStep");
  before_.steps = s.at("steps").get<long>();
  before_.rejected = s.at("rejected_steps").get<long>();
  before_.stage_solves = saved_count(s, "stage_solves");
  before_.krylov = saved_count(s, "krylov_iterations");
  before_.stability_limited = saved_count(s, "stability_limited_steps");
  before_.accuracy_limited = saved_count(s, "accuracy_limited_steps");
}

IntegratorStats ArkodeImex::stats() const {
  IntegratorStats s;
  const Counts c = counts();
  s.steps = c.steps;
  s.rejected_steps = c.rejected;
  ARKStepGetLastStep(mem_, &s.last_step);
  return s;
}

}  // namespace sphmol
