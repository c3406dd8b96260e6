#include "sphmol/time/viscous_solve.hpp"

#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_pcg.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sphmol/config/yaml_reader.hpp"
#include "sphmol/time/fixed_point_norm.hpp"
#include "sphmol/time/vector_ops.hpp"

namespace sphmol {

ViscousSolve::ViscousSolve(KrylovOptions o) : opt_(std::move(o)) {
  if (opt_.solver != "pcg" && opt_.solver != "spgmr")
    throw std::invalid_argument("time.krylov.solver: unknown '" + opt_.solver + "' (pcg or spgmr)");
  if (SUNContext_Create(nullptr, &ctx_) != 0) throw std::runtime_error("SUNContext_Create failed");
}

ViscousSolve::~ViscousSolve() {
  if (ls_) SUNLinSolFree(ls_);
  if (x_) N_VDestroy(x_);
  if (b_) N_VDestroy(b_);
  if (w_) N_VDestroy(w_);
  if (ctx_) SUNContext_Free(&ctx_);
}

void ViscousSolve::resize(const ViscousOperator& op) {
  const std::size_t n = op.size();
  const RemoteColumns* remote = op.remote();
  // Over ranks the same distribution means the same length on every rank: either every rank makes
  // new vectors (a collective) or none does.
  const std::uint64_t distribution = remote ? remote->distribution() : 0;
  if (ls_ && n == n_ && (remote != nullptr) == distributed_ && distribution == distribution_) return;
  if (ls_) SUNLinSolFree(ls_);
  if (x_) N_VDestroy(x_);
  if (b_) N_VDestroy(b_);
  if (w_) N_VDestroy(w_);
  n_ = n;
  distributed_ = remote != nullptr;
  distribution_ = distribution;
  // Dot products summed exactly (time/fixed_point_norm.hpp): the Krylov iterates do not depend on
  // the order of the additions, so that a run over threads or ranks takes the serial run's.
  if (remote) {
    x_ = remote->new_vector(n, ctx_);
  } else {
    x_ = N_VNew_Serial(static_cast<sunindextype>(n), ctx_);
    use_fixed_point_dot(x_);
    use_compiled_linear_ops(x_);
  }
  b_ = N_VClone(x_);
  w_ = N_VClone(x_);
  // Right preconditioning for GMRES, so that its test is on the true residual; PCG is symmetric.
  ls_ = opt_.solver == "pcg" ? SUNLinSol_PCG(x_, SUN_PREC_LEFT, opt_.max_iterations, ctx_)
                             : SUNLinSol_SPGMR(x_, SUN_PREC_RIGHT, opt_.max_iterations, ctx_);
  if (!ls_) throw std::runtime_error("SUNDIALS: creating the Krylov solver failed");
  if (SUNLinSolSetATimes(ls_, this, &ViscousSolve::atimes) != 0 ||
      SUNLinSolSetPreconditioner(ls_, this, nullptr, &ViscousSolve::psolve) != 0 || SUNLinSolInitialize(ls_) != 0)
    throw std::runtime_error("SUNDIALS: setting up the Krylov solver failed");
}

int ViscousSolve::atimes(void* self, N_Vector v, N_Vector z) {
  auto* me = static_cast<ViscousSolve*>(self);
  const double* vv = N_VGetArrayPointer(v);
  double* zz = N_VGetArrayPointer(z);
  me->op_->apply(vv, zz);
  const double g = me->gamma_;
  const std::size_t n = me->n_;
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < n; ++k) zz[k] = vv[k] - g * zz[k];
  return 0;
}

int ViscousSolve::psolve(void* self, N_Vector r, N_Vector z, double, int) {
  auto* me = static_cast<ViscousSolve*>(self);
  const double* rr = N_VGetArrayPointer(r);
  double* zz = N_VGetArrayPointer(z);
  const auto& diag = me->op_->diagonal();
  const std::size_t rows = me->op_->rows(), n = me->n_;
  const double g = me->gamma_;
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < n; ++k) zz[k] = rr[k] / (1.0 - g * diag[k % rows]);
  return 0;
}

int ViscousSolve::run(const ViscousOperator& op, double gamma, const double* w, double delta, bool zero_guess) {
  op_ = &op;
  gamma_ = gamma;
  if (w) std::copy(w, w + n_, N_VGetArrayPointer(w_));
  // PCG scales the residual by its first vector, GMRES by both (P^-1 b and x).
  SUNLinSolSetScalingVectors(ls_, w ? w_ : nullptr, w && opt_.solver != "pcg" ? w_ : nullptr);
  SUNLinSolSetZeroGuess(ls_, zero_guess ? SUNTRUE : SUNFALSE);
  SUNLinSolSetup(ls_, nullptr);
  const int flag = SUNLinSolSolve(ls_, nullptr, x_, b_, delta);
  last_its_ = SUNLinSolNumIters(ls_);
  last_res_ = SUNLinSolResNorm(ls_);
  iterations_ += last_its_;
  ++solves_;
  return flag;
}

int ViscousSolve::solve(const ViscousOperator& op, double gamma, const double* r, double* x) {
  const std::size_t n = op.size();
  if (n == 0 && !op.remote()) return 0;  // over ranks, a rank without fluid still takes part
  resize(op);
  double* xx = N_VGetArrayPointer(x_);
  double* bb = N_VGetArrayPointer(b_);
  std::copy(r, r + n, bb);
  std::copy(x, x + n, xx);
  const double norm = std::sqrt(N_VDotProd(b_, b_));
  if (norm == 0.0) {
    std::fill(x, x + n, 0.0);
    return 0;
  }
  // Warm start: x holds the caller's guess.
  const int flag = run(op, gamma, nullptr, opt_.tolerance * norm, false);
  if (flag != SUNLS_SUCCESS)
    throw std::runtime_error("time.krylov: " + opt_.solver + " did not reach the tolerance " + number_text(opt_.tolerance) +
                             " in " + std::to_string(last_its_) + " iterations (time.krylov.max_iterations = " +
                             std::to_string(opt_.max_iterations) + "; flag " + std::to_string(flag) + ")");
  std::copy(xx, xx + n, x);
  return last_its_;
}

int ViscousSolve::solve_weighted(const ViscousOperator& op, double gamma, const double* r, double* x, const double* w,
                                  double delta, bool zero_guess) {
  const std::size_t n = op.size();
  last_its_ = 0;
  last_res_ = 0.0;
  if (n == 0 && !op.remote()) return SUNLS_SUCCESS;
  resize(op);
  std::copy(r, r + n, N_VGetArrayPointer(b_));
  std::copy(x, x + n, N_VGetArrayPointer(x_));
  const int flag = run(op, gamma, w, delta, zero_guess);
  const double* xx = N_VGetArrayPointer(x_);
  std::copy(xx, xx + n, x);
  return flag;
}

}  // namespace sphmol
