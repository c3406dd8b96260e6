#include "sphmol/time/leapfrog.hpp"

#include "sphmol/io/double_codec.hpp"

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
  cfl_step_ = sys.stable_step();
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
  cfl_step_ = sys_->stable_step();
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

double Leapfrog::step_toward(double tout) {
  if (t_ >= tout) return t_;
  double dt = opt_.fixed_step ? *opt_.fixed_step : cfl_step_;
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
  return t_;
}

void Leapfrog::advance(double tout) {
  while (t_ < tout) step_toward(tout);
}

nlohmann::json Leapfrog::save_state() const {
  // Hex of the raw doubles: exact, and NaN/inf survive (JSON numbers would not).
  return {{"f", encode_doubles(f_)}, {"c", encode_doubles(c_)}, {"cfl_step", encode_doubles({cfl_step_})},
          {"steps", stats_.steps}, {"last_step", encode_doubles({stats_.last_step})}};
}

void Leapfrog::restore_state(const nlohmann::json& s) {
  const auto f = decode_doubles(s.at("f").get<std::string>());
  const auto c = decode_doubles(s.at("c").get<std::string>());
  const auto h = decode_doubles(s.at("cfl_step").get<std::string>());
  if (f.size() != f_.size() || c.size() != c_.size() || h.size() != 1)
    throw std::runtime_error("leapfrog: checkpoint state does not match this system (sizes differ)");
  f_ = f;
  c_ = c;
  cfl_step_ = h[0];
  stats_.steps = s.at("steps").get<long>();
  stats_.last_step = decode_doubles(s.at("last_step").get<std::string>()).at(0);
}

}  // namespace sphmol
