#pragma once
// What an implicit-explicit integrator (time/arkode_imex.hpp, time/leapfrog_imex.hpp) needs beyond
// OdeSystem: the split f = f_E + f_I of one evaluation, with f_I = L v + b affine in the fluid
// velocities (time/viscous_operator.hpp), and the velocity block's place in the state.
#include <string>
#include <vector>

#include "sphmol/time/ode_system.hpp"
#include "sphmol/time/viscous_operator.hpp"

namespace sphmol {

class ImexSystem {
 public:
  virtual ~ImexSystem() = default;
  // f_E(t, y) into fe (length size()) and the operator of f_I at the same state into op. The CFL
  // limit left by this evaluation (stable_step) covers the explicit part only: acoustic and force
  // limits, no viscous limit.
  virtual void rhs_explicit(double t, const double* y, double* fe, ViscousOperator& op) = 0;
  // Names of the terms of the implicit part (empty: nothing to treat implicitly).
  virtual std::vector<std::string> implicit_terms() const = 0;
};

}  // namespace sphmol
