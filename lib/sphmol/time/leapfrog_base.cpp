#include "sphmol/time/leapfrog_base.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "sphmol/io/double_codec.hpp"
#include "sphmol/time/blow_up.hpp"

namespace sphmol {

nlohmann::json LeapfrogBase::describe() const {
  nlohmann::json j{{"name", name()}, {"scheme", scheme()}};
  if (opt_.fixed_step) j["dt"] = *opt_.fixed_step;
  else j["step"] = "cfl";
  return j;
}

void LeapfrogBase::initialize(OdeSystem& sys, double t0, double* y) {
  sys_ = &sys;
  y_ = y;
  t_ = t0;
  f_.assign(sys.size(), 0.0);
  sys.rhs(t0, y, f_.data());  // a_0 (and the XSPH correction c_0) start the first step
  evaluated();
  initialized();
}

double LeapfrogBase::step_toward(double tout) {
  if (t_ >= tout) return t_;
  double dt = opt_.fixed_step ? *opt_.fixed_step : cfl_step_;
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw BlowUp(t_, -1, "step-size collapse: the CFL step is " + std::to_string(dt));
  // Land exactly on the output time; absorb a remainder below 1e-9 dt into this step.
  const bool last = t_ + dt * (1.0 + 1e-9) >= tout;
  if (last) dt = tout - t_;
  if (stats_.steps >= opt_.max_steps)
    throw std::runtime_error(name() + ": time.max_steps = " + std::to_string(opt_.max_steps) + " reached at t = " +
                             std::to_string(t_));
  step(dt);
  t_ = last ? tout : t_ + dt;
  ++stats_.steps;
  stats_.last_step = dt;
  after_step(t_, y_, dt);
  return t_;
}

void LeapfrogBase::advance(double tout) {
  while (t_ < tout) step_toward(tout);
}

nlohmann::json LeapfrogBase::save_state() const {
  // Hex of the raw doubles: exact, and NaN/inf survive (JSON numbers would not).
  nlohmann::json j{{"f", encode_doubles(f_)}, {"cfl_step", encode_doubles({cfl_step_})}, {"steps", stats_.steps},
                   {"last_step", encode_doubles({stats_.last_step})}};
  save_extra(j);
  return j;
}

void LeapfrogBase::restore_state(const nlohmann::json& s) {
  if (!s.contains("f") || !s.contains("cfl_step"))
    throw std::runtime_error(name() + ": the checkpoint holds no " + name() +
                             " state (written by an older sph-mol, which did not checkpoint it)");
  const auto f = decode_doubles(s.at("f").get<std::string>());
  const auto h = decode_doubles(s.at("cfl_step").get<std::string>());
  if (f.size() != f_.size() || h.size() != 1)
    throw std::runtime_error(name() + ": checkpoint state does not match this system (sizes differ)");
  f_ = f;
  cfl_step_ = h[0];
  stats_.steps = s.at("steps").get<long>();
  stats_.last_step = decode_doubles(s.at("last_step").get<std::string>()).at(0);
  restore_extra(s);
}

}  // namespace sphmol
