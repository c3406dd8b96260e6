#pragma once
// Kick-drift-kick leapfrog (velocity Verlet):
//   v_{n+1/2} = v_n + dt/2 a_n,   x_{n+1} = x_n + dt v_{n+1/2},   v_{n+1} = v_{n+1/2} + dt/2 a_{n+1}
// One RHS evaluation per step, at the end of the step. Viscous forces depend on velocity, so
// a_{n+1} is evaluated with the predicted v_{n+1/2} + dt/2 a_n (an O(dt^2) error in a_{n+1}, times
// dt/2: second order is kept). The drift adds the XSPH correction c = dx/dt - v of the latest
// evaluation; further first-order fields use the trapezoidal rule with the same predictor.
// Fixed dt, or the CFL step of the latest evaluation.
#include <optional>
#include <vector>

#include "sphmol/time/integrator.hpp"

namespace sphmol {

class LeapfrogKdk final : public Integrator {
 public:
  struct Options {
    std::optional<double> fixed_step;
    long max_steps = 10'000'000;
  };
  explicit LeapfrogKdk(Options o) : opt_(o) {}

  std::string name() const override { return "leapfrog_kdk"; }
  nlohmann::json describe() const override;
  void initialize(OdeSystem& sys, double t0, double* y) override;
  void advance(double tout) override;
  IntegratorStats stats() const override { return stats_; }

 private:
  void step(double dt);

  Options opt_;
  OdeSystem* sys_ = nullptr;
  double* y_ = nullptr;
  double t_ = 0.0;
  std::vector<double> f_, ypred_, fnew_;
  IntegratorStats stats_;
};

}  // namespace sphmol
