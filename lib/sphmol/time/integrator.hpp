#pragma once
// An ODE integrator advancing a state vector it does not own (the N_Vector / leapfrog view wraps
// the caller's storage) to requested output times.
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "sphmol/config/config.hpp"
#include "sphmol/time/ode_system.hpp"

namespace sphmol {

struct IntegratorStats {
  long steps = 0;
  long rejected_steps = 0;  // error-test failures (adaptive ERK); 0 for fixed steps
  double last_step = 0.0;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string name() const = 0;
  virtual nlohmann::json describe() const = 0;  // the summary's "integrator" object
  // y: the state, length sys.size(); it is advanced in place.
  virtual void initialize(OdeSystem& sys, double t0, double* y) = 0;
  // Advance y to exactly tout (> current time).
  virtual void advance(double tout) = 0;
  virtual IntegratorStats stats() const = 0;

  // Called after every accepted step with the new time, state and the step just taken; it may
  // throw to end the run (run/health_check.hpp: blow-up detection).
  using StepHook = std::function<void(double t, const double* y, double h)>;
  void set_step_hook(StepHook hook) { hook_ = std::move(hook); }

  // One step toward tout, never past it (the last one lands on it); returns the new time.
  // advance(tout) takes the same steps; the run loop steps one at a time so it can show progress
  // and react to a signal between steps. The default (one advance) suits integrators without it.
  virtual double step_toward(double tout) {
    advance(tout);
    return tout;
  }
  // Checkpoint/restart: what the integrator needs beyond (t, y) to continue. restore_state() is
  // called right after initialize(sys, t, y) with the checkpoint's t and y. The default (nothing
  // saved) restarts the integrator fresh from (t, y): correct, but not step-for-step identical.
  virtual nlohmann::json save_state() const { return nlohmann::json::object(); }
  virtual void restore_state(const nlohmann::json& state) {}

  // Between steps, the state was moved between processes (a repartition over MPI ranks): `y`, of
  // sys.size() values now, holds the same whole state at the same time in a new share, and every
  // vector made by make_state_vector and cloned from it moved with it (time/state_vector.hpp). An
  // integrator that keeps its step history through that (can_resize) goes on with the steps it would
  // have taken; the others (the leapfrogs) are started again by the caller from their saved state.
  virtual bool can_resize() const { return false; }
  virtual void resize(OdeSystem& sys, double t, double* y) {}

  // Between steps, an event changed the system (fluid particles taken out, run/outflow.hpp): at the
  // same time t and state y, f(t, y) is no longer what the integrator last evaluated. Starts the
  // steps again from (t, y) as initialize() does (the leapfrogs evaluate f there), keeping the step
  // counts. The SUNDIALS integrators override it to free what their first start made.
  virtual void restart(OdeSystem& sys, double t, double* y) { initialize(sys, t, y); }

 protected:
  void after_step(double t, const double* y, double h) const {
    if (hook_) hook_(t, y, h);
  }

 private:
  StepHook hook_;
};

std::unique_ptr<Integrator> make_integrator(const TimeConfig& time);

}  // namespace sphmol
