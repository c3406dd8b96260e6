#pragma once
// Solves (I - gamma L) x = r for the implicit viscous operator L (time/viscous_operator.hpp) on the
// velocity block with a SUNDIALS Krylov solver used directly (SUNLinSolSetup / SUNLinSolSolve with an
// ATimes callback): preconditioned conjugate gradients (SUNLinSol_PCG) where L is symmetric, GMRES
// (SUNLinSol_SPGMR) otherwise. Jacobi preconditioner (the diagonal 1 - gamma L_ii), warm start from x.
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_nvector.h>

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
  long total_iterations() const { return iterations_; }

 private:
  static int atimes(void* self, N_Vector v, N_Vector z);
  static int psolve(void* self, N_Vector r, N_Vector z, double tol, int lr);
  void resize(std::size_t n);

  KrylovOptions opt_;
  SUNContext ctx_ = nullptr;
  SUNLinearSolver ls_ = nullptr;
  N_Vector x_ = nullptr, b_ = nullptr;
  std::size_t n_ = 0;
  const ViscousOperator* op_ = nullptr;
  double gamma_ = 0.0;
  long iterations_ = 0;
};

}  // namespace sphmol
