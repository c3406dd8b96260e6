#pragma once
// The linear solver ARKStep calls for arkode_imex's stage systems (I - gamma J) x = b, where J is
// zero except on the velocity block, where it is the frozen viscous operator L_n
// (time/viscous_operator.hpp). A SUNLinearSolver of the iterative kind whose solve takes x = b off the
// velocity block (exact there) and hands the velocity block alone to ViscousSolve (SUNDIALS PCG or
// GMRES, Jacobi preconditioner) with ARKStep's error weights and tolerance: the Krylov vectors, dot
// products and preconditioner then span the velocity block (2/5 of a 2D SPH state) instead of the
// whole state, where ARKStep's own matrix-free Krylov solver iterated on positions and densities too.
// ARKStep's residual test is on ||w r||_2 over the whole state, which the block solve meets exactly
// because the residual off the block is zero. gamma comes from the caller (arkode_imex: ARKStep's
// current one, ARKStepGetCurrentGamma).
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

#include <cstddef>
#include <exception>
#include <functional>

#include "sphmol/time/viscous_solve.hpp"

namespace sphmol {

class StageLinearSolver {
 public:
  // op: the operator of the stage systems, read at each solve (its contents may change between
  // solves, the object may not move); the velocity block is [vb, vb + op->size()) of this process's
  // `length` entries of the state.
  StageLinearSolver(SUNContext ctx, KrylovOptions k, const ViscousOperator* op, std::size_t vb, std::size_t length);
  ~StageLinearSolver();
  StageLinearSolver(const StageLinearSolver&) = delete;
  StageLinearSolver& operator=(const StageLinearSolver&) = delete;
  // Where gamma comes from; set before the first solve.
  void set_gamma(std::function<double()> gamma) { gamma_ = std::move(gamma); }
  SUNLinearSolver get() const { return ls_; }
  // The velocity block and this process's length after the state's share changed (a repartition).
  void set_block(std::size_t vb, std::size_t length) {
    vb_ = vb;
    length_ = length;
  }
  // Whether the last solve stopped at time.krylov.max_iterations short of its tolerance. Such a solve
  // is reported to ARKStep as a recoverable convergence failure (it shrinks the step and tries
  // again), not as the "residual reduced" that ARKStep accepts as solved when it makes one Newton
  // iteration per stage, as here (SetLinear).
  bool last_capped() const { return last_capped_; }
  // An exception a solve caught (it may not cross SUNDIALS' C frames), for the caller to rethrow
  // once ARKStep has returned; null if none.
  std::exception_ptr error() const { return error_; }

 private:
  static StageLinearSolver* self(SUNLinearSolver S) { return static_cast<StageLinearSolver*>(S->content); }
  static int solve(SUNLinearSolver S, SUNMatrix, N_Vector x, N_Vector b, double delta);

  SUNLinearSolver ls_ = nullptr;
  ViscousSolve solve_;
  const ViscousOperator* op_;
  std::size_t vb_, length_;
  std::function<double()> gamma_;
  N_Vector weights_ = nullptr;  // ARKStep's, set through the scaling-vector operation
  bool zero_guess_ = false;
  int last_flag_ = 0;
  bool last_capped_ = false;
  std::exception_ptr error_;
};

}  // namespace sphmol
