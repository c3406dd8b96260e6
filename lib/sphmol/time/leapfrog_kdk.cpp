#include "sphmol/time/leapfrog_kdk.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "sphmol/time/blow_up.hpp"

namespace sphmol {

nlohmann::json LeapfrogKdk::describe() const {
  nlohmann::json j{{"name", name()}, {"scheme", "kick-drift-kick (velocity Verlet)"}};
  if (opt_.fixed_step) j["dt"] = *opt_.fixed_step;
  else j["step"] = "cfl";
  return j;
}

void LeapfrogKdk::initialize(OdeSystem& sys, double t0, double* y) {
  sys_ = &sys;
  y_ = y;
  t_ = t0;
  const std::size_t n = sys.size();
  f_.assign(n, 0.0);
  ypred_.assign(n, 0.0);
  fnew_.assign(n, 0.0);
  sys.rhs(t0, y, f_.data());  // a_0
}

void LeapfrogKdk::step(double dt) {
  const std::size_t vb = sys_->velocities_begin(), ve = sys_->velocities_end(), n = sys_->size();
  const std::size_t nv = ve - vb;  // positions occupy [0, nv): one per velocity component
  double* y = y_;
  // Drift with v_{n+1/2} plus the XSPH correction c_n = f_pos - v_n of the latest evaluation.
  for (std::size_t k = 0; k < nv; ++k) {
    const double c = f_[k] - y[vb + k];
    const double vhalf = y[vb + k] + 0.5 * dt * f_[vb + k];
    y[k] += dt * (vhalf + c);
  }
  // Half kick; the prediction for the evaluation at t_{n+1} is one more half kick with a_n.
  for (std::size_t k = 0; k < nv; ++k) ypred_[k] = y[k];
  for (std::size_t k = vb; k < ve; ++k) {
    y[k] += 0.5 * dt * f_[k];
    ypred_[k] = y[k] + 0.5 * dt * f_[k];
  }
  for (std::size_t k = ve; k < n; ++k) ypred_[k] = y[k] + dt * f_[k];
  sys_->rhs(t_ + dt, ypred_.data(), fnew_.data());
  for (std::size_t k = vb; k < ve; ++k) y[k] += 0.5 * dt * fnew_[k];
  for (std::size_t k = ve; k < n; ++k) y[k] += 0.5 * dt * (f_[k] + fnew_[k]);
  f_.swap(fnew_);
  t_ += dt;
  ++stats_.steps;
  stats_.last_step = dt;
}

void LeapfrogKdk::advance(double tout) {
  while (t_ < tout) {
    double dt = opt_.fixed_step ? *opt_.fixed_step : sys_->stable_step();
    if (!(dt > 0.0) || !std::isfinite(dt)) throw BlowUp(t_, -1, "step-size collapse: the CFL step is " + std::to_string(dt));
    // Land exactly on the output time; absorb a remainder below 1e-9 dt into this step.
    const bool last = t_ + dt * (1.0 + 1e-9) >= tout;
    if (last) dt = tout - t_;
    if (stats_.steps >= opt_.max_steps)
      throw std::runtime_error("leapfrog_kdk: time.max_steps = " + std::to_string(opt_.max_steps) + " reached at t = " + std::to_string(t_));
    step(dt);
    if (last) t_ = tout;
    after_step(t_, y_, dt);
  }
}

}  // namespace sphmol
