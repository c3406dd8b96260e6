#pragma once
// What the two built-in leapfrogs (leapfrog.hpp: drift-kick-drift, leapfrog_kdk.hpp: kick-drift-kick)
// share: one RHS evaluation per step whose result f (and CFL step) starts the next step, a fixed or
// CFL step that lands exactly on output times, one step at a time through step_toward() (so the run
// loop sees signals and progress every step), the step hook, and checkpoint state (the last RHS
// f, the position correction c, the cached CFL step and the counters) that makes an interrupted +
// restarted run bit-identical.
//
// The position correction c = dx/dt - v (XSPH, the transport velocity) is kept per position
// component, relative to the velocity the evaluation was made with (the schemes evaluate at predicted
// velocities, so f's position block minus the current v is not c). Each scheme integrates it at
// second order: its lag behind the step is taken back once the step's evaluation has given the new c.
#include <optional>
#include <vector>

#include "sphmol/time/integrator.hpp"

namespace sphmol {

class LeapfrogBase : public Integrator {
 public:
  struct Options {
    std::optional<double> fixed_step;
    long max_steps = 10'000'000;
  };

  nlohmann::json describe() const override;
  void initialize(OdeSystem& sys, double t0, double* y) override;
  void advance(double tout) override;
  IntegratorStats stats() const override { return stats_; }
  double step_toward(double tout) override;
  nlohmann::json save_state() const override;
  void restore_state(const nlohmann::json& state) override;

 protected:
  explicit LeapfrogBase(Options o) : opt_(o) {}
  virtual const char* scheme() const = 0;
  // One step of length dt from (t_, y_): evaluates the RHS once, leaves that evaluation in f_, and
  // calls evaluated() right after the evaluation. Does not touch t_ or the counters.
  virtual void step(double dt) = 0;
  // Hooks for the scheme's own state beyond f_ (called at the end of initialize, in save/restore).
  virtual void initialized() {}
  virtual void save_extra(nlohmann::json&) const {}
  virtual void restore_extra(const nlohmann::json&) {}
  // Caches the CFL step of the evaluation just made, so that other rhs() calls on the system (output
  // fields, VTK) cannot change the step sequence.
  void evaluated() { cfl_step_ = sys_->stable_step(); }

  Options opt_;
  OdeSystem* sys_ = nullptr;
  double* y_ = nullptr;
  double t_ = 0.0;
  std::vector<double> f_;  // RHS of the latest own evaluation
  std::vector<double> c_;  // position correction of the latest own evaluation, per position component

 private:
  // c = f's position block minus the velocity in y_ (exact where f was evaluated at y_).
  void correction_from_f();

  IntegratorStats stats_;
  double cfl_step_ = 0.0;
};

}  // namespace sphmol
