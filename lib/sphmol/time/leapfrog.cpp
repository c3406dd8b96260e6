#include "sphmol/time/leapfrog.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "sphmol/time/blow_up.hpp"

namespace sphmol {

nlohmann::json Leapfrog::describe() const {
  nlohmann::json j{{"name", name()}, {"scheme", "drift-kick-drift (seed 002 eq 22)"}};
  if (opt_.fixed_step) j["dt"] = *opt_.fixed_step;
  else j["step"] = "cfl";
  return j;
}

void Leapfrog::initialize(OdeSystem& sys, double t0, double* y) {
  sys_ = &sys;
  y_ = y;
  t_ = t0;
  const std::size_t n = sys.size();
  f_.assign(n, 0.0);
  ymid_.assign(n, 0.0);
  fmid_.assign(n, 0.0);
  sys.rhs(t0, y, f_.data());  // a_0 and c_0 start the predictor
  const std::size_t vb = sys.velocities_begin(), nv = sys.velocities_end() - vb;
  c_.resize(nv);
  for (std::size_t k = 0; k < nv; ++k) c_[k] = f_[k] - y[vb + k];
}

void Leapfrog::step(double dt) {
  const std::size_t vb = sys_->velocities_begin(), ve = sys_->velocities_end(), n = sys_->size();
  const std::size_t nv = ve - vb;  // positions occupy [0, nv): one per velocity component
  double* y = y_;
  // Half drift with v_n plus the latest XSPH correction; predicted half-step velocity; midpoint
  // prediction for other fields.
  for (std::size_t k = 0; k < nv; ++k) ymid_[k] = y[k] + 0.5 * dt * (y[vb + k] + c_[k]);
  for (std::size_t k = vb; k < ve; ++k) ymid_[k] = y[k] + 0.5 * dt * f_[k];
  for (std::size_t k = ve; k < n; ++k) ymid_[k] = y[k] + 0.5 * dt * f_[k];
  sys_->rhs(t_ + 0.5 * dt, ymid_.data(), fmid_.data());
  // Kick, second half drift with v_{n+1}, midpoint for the rest.
  for (std::size_t k = vb; k < ve; ++k) y[k] += dt * fmid_[k];
  for (std::size_t k = 0; k < nv; ++k) {
    c_[k] = fmid_[k] - ymid_[vb + k];  // XSPH correction relative to the velocity it was evaluated with
    y[k] = ymid_[k] + 0.5 * dt * (y[vb + k] + c_[k]);
  }
  for (std::size_t k = ve; k < n; ++k) y[k] += dt * fmid_[k];
  f_.swap(fmid_);
  t_ += dt;
  ++stats_.steps;
  stats_.last_step = dt;
}

void Leapfrog::advance(double tout) {
  while (t_ < tout) {
    double dt = opt_.fixed_step ? *opt_.fixed_step : sys_->stable_step();
    if (!(dt > 0.0) || !std::isfinite(dt))
      throw BlowUp(t_, -1, "step-size collapse: the CFL step is " + std::to_string(dt));
    // Land exactly on the output time; absorb a remainder below 1e-9 dt into this step.
    const bool last = t_ + dt * (1.0 + 1e-9) >= tout;
    if (last) dt = tout - t_;
    if (stats_.steps >= opt_.max_steps)
      throw std::runtime_error("leapfrog: time.max_steps = " + std::to_string(opt_.max_steps) + " reached at t = " + std::to_string(t_));
    step(dt);
    if (last) t_ = tout;
    after_step(t_, y_, dt);
  }
}

}  // namespace sphmol
