#include "sphmol/time/leapfrog_base.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sphmol/io/double_codec.hpp"
#include "sphmol/time/blow_up.hpp"
#include "sphmol/time/step_limit.hpp"

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
  sys.rhs(t0, y, f_.data());  // a_0 (and the position correction c_0) start the first step
  evaluated();
  c_.resize(sys.velocities_end() - sys.velocities_begin());  // one per position component
  correction_from_f();
  initialized();
}

void LeapfrogBase::correction_from_f() {
  const std::size_t vb = sys_->velocities_begin();
  for (std::size_t k = 0; k < c_.size(); ++k) c_[k] = f_[k] - y_[vb + k];
}

double LeapfrogBase::step_toward(double tout) {
  const bool fixed = opt_.fixed_step.has_value();
  double dt = fixed ? *opt_.fixed_step : cfl_step_;
  if (t_ >= tout) return t_;
  // On a fixed step's grid point that stands for tout (below): already there.
  if (fixed && std::abs(tout - t_) <= 1e-9 * dt) return tout;
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw BlowUp(t_, -1, "step-size collapse: the CFL step is " + std::to_string(dt));
  check_step_limit(name(), stats_.steps, opt_.max_steps, t_);
  double t_new = 0.0;
  if (fixed) {
    // Steps on the grid t_k = k dt, each computed from k (not accumulated), so that where the run
    // stops for output cannot change the step sequence: accumulated t_ + dt drifts by round-off, and
    // the step shortened to land on an output time then differs in its last bits from run to run
    // with other output lists, which a chaotic flow (cavity at Re 1000) amplifies to O(1) within
    // seconds. An output time within 1e-9 dt of a grid point is that grid point; one between grid
    // points splits the step there (the only case where output times change the solution).
    const double k_near = std::nearbyint(t_ / dt);
    const double k = std::abs(t_ - k_near * dt) <= 1e-9 * dt ? k_near : std::floor(t_ / dt);
    const double t_grid = (k + 1.0) * dt;
    const bool lands = std::abs(t_grid - tout) <= 1e-9 * dt;
    t_new = (lands || t_grid < tout) ? t_grid : tout;
    dt = t_new - t_;
    step(dt);
    t_ = t_new;
    ++stats_.steps;
    stats_.last_step = dt;
    after_step(t_, y_, dt);
    return lands ? tout : t_;
  }
  // CFL step: land exactly on the output time; absorb a remainder below 1e-9 dt into this step.
  const bool last = t_ + dt * (1.0 + 1e-9) >= tout;
  if (last) dt = tout - t_;
  step(dt);
  t_ = last ? tout : t_ + dt;
  ++stats_.steps;
  stats_.last_step = dt;
  after_step(t_, y_, dt);
  return t_;
}

void LeapfrogBase::advance(double tout) {
  for (double t = t_; t < tout;) t = step_toward(tout);
}

nlohmann::json LeapfrogBase::save_state() const {
  // Hex of the raw doubles: exact, and NaN/inf survive (JSON numbers would not).
  nlohmann::json j{{"f", encode_doubles(f_)}, {"cfl_step", encode_doubles({cfl_step_})}, {"steps", stats_.steps},
                   {"last_step", encode_doubles({stats_.last_step})},
                   {"t", encode_doubles({t_})},  // the grid time, which may differ from the run's t in the last bit
                   {"c", encode_doubles(c_)}};
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
  // The grid time it stopped at stands for the checkpoint's time (initialize set t_ to it): one that
  // does not is not this run's.
  if (s.contains("t")) {
    const double tg = decode_doubles(s.at("t").get<std::string>()).at(0);
    if (!std::isfinite(tg) || std::abs(tg - t_) > 1e-9 * std::max(1.0, std::abs(t_)))
      throw std::runtime_error(name() + ": checkpoint step time " + std::to_string(tg) + " does not match its time " + std::to_string(t_));
    t_ = tg;
  }
  if (s.contains("c")) {
    const auto c = decode_doubles(s.at("c").get<std::string>());
    if (c.size() != c_.size()) throw std::runtime_error(name() + ": checkpoint state does not match this system (sizes differ)");
    c_ = c;
  } else {
    // Written before leapfrog_kdk and leapfrog_imex kept c: they took f's position block minus the
    // current velocity, which is what this sets (an O(dt^2) difference from c, for one step).
    correction_from_f();
  }
  restore_extra(s);
}

}  // namespace sphmol
