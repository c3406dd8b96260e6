#pragma once
// Solves (I - gamma L) x = r for the implicit viscous operator L (time/viscous_operator.hpp) on the
// velocity block with a SUNDIALS Krylov solver used directly (SUNLinSolSetup / SUNLinSolSolve with an
// ATimes callback): preconditioned conjugate gradients (SUNLinSol_PCG) where L is symmetric, GMRES
// (SUNLinSol_SPGMR) otherwise. Jacobi preconditioner (the diagonal 1 - gamma L_ii), warm start from x.
// Its dot products are summed exactly (time/fixed_point_norm.hpp), and over MPI ranks reduced over
// them (time/remote_columns.hpp): the iterates are the same bits on any thread or rank count.
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_nvector.h>

#include <cstdint>
#include <string>

#include "sphmol/time/viscous_operator.hpp"

namespace sphmol {

struct KrylovOptions {
  std::string solver = "pcg";  // pcg | spgmr
  double tolerance = 1e-8;     // on ||r - (I - gamma L) x||_2 / ||r||_2
  int max_iterations = 100;
};

class ViscousSolve {
 public:
  explicit ViscousSolve(KrylovOptions o);
  ~ViscousSolve();
  ViscousSolve(const ViscousSolve&) = delete;
  ViscousSolve& operator=(const ViscousSolve&) = delete;

  // x (in: initial guess, out: solution) and r: velocity blocks of op.size() values. Returns the
  // Krylov iterations taken; throws std::runtime_error when the solver does not converge.
  int solve(const ViscousOperator& op, double gamma, const double* r, double* x);
  // As solve, but stops at ||w (r - (I - gamma L) x)||_2 <= delta for the weights w (op.size()
  // values; null: unweighted), and returns the SUNDIALS flag (SUNLS_SUCCESS, or why not) instead of
  // throwing. zero_guess: x holds zeros (saves the first product).
  int solve_weighted(const ViscousOperator& op, double gamma, const double* r, double* x, const double* w, double delta,
                      bool zero_guess);
  int last_iterations() const { return last_its_; }
  double last_residual() const { return last_res_; }
  long total_iterations() const { return iterations_; }
  long total_solves() const { return solves_; }  // Krylov solves run (each of solve, solve_weighted)

 private:
  static int atimes(void* self, N_Vector v, N_Vector z);
  static int psolve(void* self, N_Vector r, N_Vector z, double tol, int lr);
  // Krylov vectors for op's velocity block (serial, or over the ranks of op.remote()).
  void resize(const ViscousOperator& op);
  // The Krylov solve of (I - gamma L) x = r into x_ from b_ (and the guess in x_); the SUNDIALS flag.
  int run(const ViscousOperator& op, double gamma, const double* w, double delta, bool zero_guess);

  KrylovOptions opt_;
  SUNContext ctx_ = nullptr;
  SUNLinearSolver ls_ = nullptr;
  N_Vector x_ = nullptr, b_ = nullptr, w_ = nullptr;
  std::size_t n_ = 0;
  bool distributed_ = false;
  std::uint64_t distribution_ = 0;
  const ViscousOperator* op_ = nullptr;
  double gamma_ = 0.0;
  long iterations_ = 0;
  long solves_ = 0;
  int last_its_ = 0;
  double last_res_ = 0.0;
};

}  // namespace sphmol
