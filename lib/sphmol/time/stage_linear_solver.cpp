#include "sphmol/time/stage_linear_solver.hpp"

#include <stdexcept>
#include <utility>

namespace sphmol {

StageLinearSolver::StageLinearSolver(SUNContext ctx, KrylovOptions k, const ViscousOperator* op, std::size_t vb,
                                     std::size_t length)
    : solve_(std::move(k)), op_(op), vb_(vb), length_(length) {
  ls_ = SUNLinSolNewEmpty(ctx);
  if (!ls_) throw std::runtime_error("SUNDIALS: creating the stage linear solver failed");
  ls_->content = this;
  auto* ops = ls_->ops;
  ops->gettype = [](SUNLinearSolver) { return SUNLINEARSOLVER_ITERATIVE; };
  ops->getid = [](SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; };
  // ARKStep requires an iterative solver to take its ATimes and preconditioner; the block solve
  // applies L_n itself, so both are accepted and not used.
  ops->setatimes = [](SUNLinearSolver, void*, SUNATimesFn) { return SUNLS_SUCCESS; };
  ops->setpreconditioner = [](SUNLinearSolver, void*, SUNPSetupFn, SUNPSolveFn) { return SUNLS_SUCCESS; };
  ops->setscalingvectors = [](SUNLinearSolver S, N_Vector s1, N_Vector) {
    self(S)->weights_ = s1;
    return SUNLS_SUCCESS;
  };
  ops->setzeroguess = [](SUNLinearSolver S, booleantype z) {
    self(S)->zero_guess_ = z == SUNTRUE;
    return SUNLS_SUCCESS;
  };
  ops->initialize = [](SUNLinearSolver) { return SUNLS_SUCCESS; };
  ops->setup = [](SUNLinearSolver, SUNMatrix) { return SUNLS_SUCCESS; };
  ops->solve = &StageLinearSolver::solve;
  ops->numiters = [](SUNLinearSolver S) { return self(S)->solve_.last_iterations(); };
  ops->resnorm = [](SUNLinearSolver S) { return self(S)->solve_.last_residual(); };
  ops->lastflag = [](SUNLinearSolver S) { return static_cast<sunindextype>(self(S)->last_flag_); };
  ops->free = nullptr;  // the destructor frees
}

StageLinearSolver::~StageLinearSolver() {
  if (ls_) SUNLinSolFreeEmpty(ls_);
}

int StageLinearSolver::solve(SUNLinearSolver S, SUNMatrix, N_Vector x, N_Vector b, double delta) {
  StageLinearSolver* me = self(S);
  if (!me->gamma_) return me->last_flag_ = SUNLS_MEM_NULL;
  // No exception may cross SUNDIALS' C frames: a failure becomes an unrecoverable flag.
  try {
    const double gamma = me->gamma_();
    const double* bb = N_VGetArrayPointer(b);
    double* xx = N_VGetArrayPointer(x);
    // This process's entries (N_VGetLength is the whole length over ranks).
    const std::size_t n = me->length_, vb = me->vb_, ve = vb + me->op_->size();
    // Off the velocity block the system is the identity.
    for (std::size_t k = 0; k < vb; ++k) xx[k] = bb[k];
    for (std::size_t k = ve; k < n; ++k) xx[k] = bb[k];
    const double* w = me->weights_ ? N_VGetArrayPointer(me->weights_) + vb : nullptr;
    me->last_flag_ = me->solve_.solve_weighted(*me->op_, gamma, bb + vb, xx + vb, w, delta, me->zero_guess_);
    me->last_capped_ = me->last_flag_ == SUNLS_RES_REDUCED;
    if (me->last_capped_) me->last_flag_ = SUNLS_CONV_FAIL;
  } catch (...) {
    me->error_ = std::current_exception();
    me->last_flag_ = SUNLS_ATIMES_FAIL_UNREC;
  }
  return me->last_flag_;
}

}  // namespace sphmol
