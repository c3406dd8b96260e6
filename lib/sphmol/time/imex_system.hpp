#pragma once
// What an implicit-explicit integrator (time/arkode_imex.hpp, time/leapfrog_imex.hpp) needs beyond
// OdeSystem: the split f = f_E + f_I of one evaluation, with f_I = L v + b affine in the fluid
// velocities (time/viscous_operator.hpp), and the velocity block's place in the state.
#include <cstddef>
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
  // Replaces `count` values by their minima over every process (collective for a system split over
  // MPI ranks; nothing to do for one process): the integrators' decisions and error weights that rest
  // on extremes of the state are then the same on every rank.
  virtual void minimum_everywhere(double* values, std::size_t count) const {
    (void)values;
    (void)count;
  }
  // Whether `mine` holds on every process: an integrator that skips an evaluation when its cache
  // holds skips it on every rank.
  bool everywhere(bool mine) const {
    double v = mine ? 1.0 : 0.0;
    minimum_everywhere(&v, 1);
    return v == 1.0;
  }
};

}  // namespace sphmol
