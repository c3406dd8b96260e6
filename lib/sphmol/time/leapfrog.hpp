#pragma once
// Built-in leapfrog of seed 002 eq 22 (drift-kick-drift):
//   x_{n+1/2} = x_n + dt/2 v_n,   v_{n+1} = v_n + dt a_{n+1/2},   x_{n+1} = x_{n+1/2} + dt/2 v_{n+1}
// One RHS evaluation per step, at the half step. Viscous forces depend on velocity, so a_{n+1/2}
// is evaluated with the predicted v_n + dt/2 a_{n-1/2} (O(dt^2) accurate, which keeps the scheme
// second order). The XSPH correction c = dx/dt - v from that evaluation is used in both drifts;
// any further first-order fields are advanced by the midpoint rule. Fixed dt, or the CFL step.
#include <optional>
#include <vector>

#include "sphmol/time/integrator.hpp"

namespace sphmol {

class Leapfrog final : public Integrator {
 public:
  struct Options {
    std::optional<double> fixed_step;
    long max_steps = 10'000'000;
  };
  explicit Leapfrog(Options o) : opt_(o) {}

  std::string name() const override { return "leapfrog"; }
  nlohmann::json describe() const override;
  void initialize(OdeSystem& sys, double t0, double* y) override;
  void advance(double tout) override;
  IntegratorStats stats() const override { return stats_; }
  double step_toward(double tout) override;
  // Saves the last RHS, the XSPH correction and the CFL step: a restart is bit-identical.
  nlohmann::json save_state() const override;
  void restore_state(const nlohmann::json& state) override;

 private:
  void step(double dt);

  Options opt_;
  OdeSystem* sys_ = nullptr;
  double* y_ = nullptr;
  double t_ = 0.0;
  std::vector<double> f_, ymid_, fmid_;
  std::vector<double> c_;  // XSPH correction dx/dt - v of the latest evaluation, per position component
  IntegratorStats stats_;
  // CFL step of the latest own evaluation, cached so that other rhs() calls on the system (output
  // fields, VTK) cannot change the step sequence.
  double cfl_step_ = 0.0;
};

}  // namespace sphmol
