#pragma once
// Kick-drift-kick leapfrog (velocity Verlet):
//   v_{n+1/2} = v_n + dt/2 a_n,   x_{n+1} = x_n + dt v_{n+1/2},   v_{n+1} = v_{n+1/2} + dt/2 a_{n+1}
// One RHS evaluation per step, at the end of the step. Viscous forces depend on velocity, so
// a_{n+1} is evaluated with the predicted v_{n+1/2} + dt/2 a_n (an O(dt^2) error in a_{n+1}, times
// dt/2: second order is kept). The position correction c = dx/dt - v (XSPH, transport velocity) and
// further first-order fields use the trapezoidal rule with the same predictor.
// Fixed dt, or the CFL step of the latest evaluation. Stepping, checkpoint state (f_ and c_ hold all
// the scheme needs) and the step hook: leapfrog_base.hpp.
#include <vector>

#include "sphmol/time/leapfrog_base.hpp"

namespace sphmol {

class LeapfrogKdk final : public LeapfrogBase {
 public:
  explicit LeapfrogKdk(Options o) : LeapfrogBase(o) {}
  std::string name() const override { return "leapfrog_kdk"; }

 private:
  const char* scheme() const override { return "kick-drift-kick (velocity Verlet)"; }
  void step(double dt) override;
  void initialized() override;

  std::vector<double> ypred_, fnew_;
};

}  // namespace sphmol
