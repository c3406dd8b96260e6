#pragma once
// Semi-implicit kick-drift-kick leapfrog: the explicit part f_E of the IMEX split
// (time/imex_system.hpp) as in leapfrog_kdk.hpp, the viscous part f_I = L v + b (time/viscous_operator.hpp)
// by the trapezoidal rule:
//   v_{n+1/2} = v_n + dt/2 (a_E,n + L_n v_n + b_n),        x_{n+1} = x_n + dt v_{n+1/2},
//   (I - dt/2 L_{n+1}) v_{n+1} = v_{n+1/2} + dt/2 (a_E,n+1 + b_{n+1}),
// with L_{n+1}, b_{n+1} and a_E,n+1 from the one evaluation of the step, at x_{n+1}. For a fixed L the
// viscous update is Crank-Nicolson: A-stable and second order, so the step is set by the acoustic and
// force limits alone. The evaluation at x_{n+1} sees a predicted velocity
// v_n + dt (v_n - v_{n-1}) / dt_{n-1} (an O(dt^2) error in the velocity-dependent explicit terms, as
// the explicit leapfrog's predictor); it is built from solved velocities, which stay bounded where
// the explicit predictor v_{n+1/2} + dt/2 a_n would amplify the stiff viscous modes. The first step
// predicts with a_n. The linear system is solved by ViscousSolve (PCG or GMRES with a Jacobi
// preconditioner), warm started from the prediction.
// The step starts from f_I,n = L_n v_n + b_n, applied at the end of the step before with the operator
// of that step's evaluation (at the predicted state); it is kept as state and checkpointed, with the
// previous velocities, so that a restart, or a start on a new share of particles over MPI ranks,
// goes on bit for bit (recording L and b again at the state would change them).
#include <vector>

#include "sphmol/time/imex_system.hpp"
#include "sphmol/time/leapfrog_base.hpp"
#include "sphmol/time/viscous_solve.hpp"

namespace sphmol {

class LeapfrogImex final : public LeapfrogBase {
 public:
  LeapfrogImex(Options o, KrylovOptions k) : LeapfrogBase(o), krylov_(k), solve_(k) {}
  std::string name() const override { return "leapfrog_imex"; }
  nlohmann::json describe() const override;
  // Krylov iterations since the run's start (those before a restart from the checkpoint).
  long krylov_iterations() const { return solve_.total_iterations() + iterations_before_; }

 private:
  const char* scheme() const override { return "kick-drift-kick with a trapezoidal implicit viscous kick"; }
  void step(double dt) override;
  void initialized() override;
  void save_extra(nlohmann::json& j) const override;
  void restore_extra(const nlohmann::json& j) override;

  KrylovOptions krylov_;
  ViscousSolve solve_;
  ImexSystem* imex_ = nullptr;
  ViscousOperator op_;  // L and b of the latest evaluation
  std::vector<double> ypred_, fnew_, vprev_, rhs_, guess_;
  std::vector<double> w_;  // f_I,n = L_n v_n + b_n, which starts the next step
  double dt_prev_ = 0.0;  // 0: no previous step (predict with a_n)
  long steps_ = 0;
  long iterations_before_ = 0, solves_before_ = 0;  // Krylov iterations and solves before a restart
};

}  // namespace sphmol
