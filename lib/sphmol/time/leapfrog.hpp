#pragma once
// Built-in leapfrog of Vukčević et al. 2012, eq 22 (drift-kick-drift):
//   x_{n+1/2} = x_n + dt/2 v_n,   v_{n+1} = v_n + dt a_{n+1/2},   x_{n+1} = x_{n+1/2} + dt/2 v_{n+1}
// One RHS evaluation per step, at the half step. Viscous forces depend on velocity, so a_{n+1/2}
// is evaluated with the predicted v_n + dt/2 a_{n-1/2} (O(dt^2) accurate, which keeps the scheme
// second order). The position correction c = dx/dt - v (XSPH, transport velocity) enters the position
// update at its midpoint value (leapfrog.cpp); any further first-order fields are advanced by the
// midpoint rule. Fixed dt, or the CFL step.
// Stepping, checkpoint state and the step hook: leapfrog_base.hpp.
#include <vector>

#include "sphmol/time/leapfrog_base.hpp"

namespace sphmol {

class Leapfrog final : public LeapfrogBase {
 public:
  explicit Leapfrog(Options o) : LeapfrogBase(o) {}
  std::string name() const override { return "leapfrog"; }

 private:
  const char* scheme() const override { return "drift-kick-drift (Vukčević et al. 2012, eq 22)"; }
  void step(double dt) override;
  void initialized() override;
  std::vector<double> ymid_, fmid_;
};

}  // namespace sphmol
