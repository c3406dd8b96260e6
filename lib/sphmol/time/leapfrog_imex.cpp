#include "sphmol/time/leapfrog_imex.hpp"

#include <stdexcept>

#include "sphmol/io/double_codec.hpp"
#include "sphmol/time/particle_split.hpp"
#include "sphmol/time/saved_count.hpp"

namespace sphmol {

nlohmann::json LeapfrogImex::describe() const {
  nlohmann::json j = LeapfrogBase::describe();
  const long steps = stats().steps;
  j["krylov"] = {{"solver", krylov_.solver}, {"tolerance", krylov_.tolerance}, {"max_iterations", krylov_.max_iterations}};
  const long its = krylov_iterations(), solves = solve_.total_solves() + solves_before_;
  j["krylov_iterations"] = its;
  j["krylov_iterations_per_step"] = steps > 0 ? static_cast<double>(its) / static_cast<double>(steps) : 0.0;
  // One viscous solve per step (the trapezoidal kick).
  j["implicit_solves"] = solves;
  j["krylov_iterations_per_solve"] = solves > 0 ? static_cast<double>(its) / static_cast<double>(solves) : 0.0;
  return j;
}

void LeapfrogImex::initialized() {
  imex_ = dynamic_cast<ImexSystem*>(sys_);
  if (!imex_) throw std::invalid_argument("time.integrator: leapfrog_imex needs a system with an implicit-explicit split");
  if (imex_->implicit_terms().empty())
    throw std::invalid_argument("time.integrator: leapfrog_imex needs an implicit (viscous) term; the scene has none");
  const std::size_t n = sys_->size(), nv = sys_->velocities_end() - sys_->velocities_begin();
  ypred_.assign(n, 0.0);
  fnew_.assign(n, 0.0);
  w_.assign(nv, 0.0);
  vprev_.assign(nv, 0.0);
  rhs_.assign(nv, 0.0);
  guess_.assign(nv, 0.0);
  // The base evaluated the full f; the scheme needs the split: f_E and L, b at the start.
  imex_->rhs_explicit(t_, y_, f_.data(), op_);
  evaluated();
  if (op_.size() != nv) throw std::logic_error("leapfrog_imex: the implicit operator does not match the velocity block");
  op_.apply_affine(y_ + sys_->velocities_begin(), w_.data());  // f_I,0 = L_0 v_0 + b_0
}

void LeapfrogImex::step(double dt) {
  const std::size_t vb = sys_->velocities_begin(), ve = sys_->velocities_end(), n = sys_->size();
  const std::size_t nv = ve - vb;
  double* const y = y_;
  double *const yp = ypred_.data(), *const fn = fnew_.data(), *const w = w_.data(), *const vp = vprev_.data();
  double* const c = c_.data();
  const double* const f = f_.data();
  const std::size_t L = sys_->block_length();
  // w = f_I,n = L_n v_n + b_n, applied at the end of the previous step (or in initialized()).
  const bool extrapolate = dt_prev_ > 0.0;
  const double ratio = extrapolate ? dt / dt_prev_ : 0.0;
#pragma omp parallel
  {
    for_each_by_particle(0, nv, L, [&](std::size_t k) {
      const double v = y[vb + k];
      const double a = f[vb + k] + w[k];
      const double vhalf = v + 0.5 * dt * a;
      y[k] += dt * (vhalf + c[k]);  // position correction c_n of the latest evaluation
      yp[k] = y[k];
      yp[vb + k] = extrapolate ? v + ratio * (v - vp[k]) : vhalf + 0.5 * dt * a;
      vp[k] = v;
      y[vb + k] = vhalf;
    });
    for_each_by_particle(ve, n, L, [&](std::size_t k) { yp[k] = y[k] + dt * f[k]; });
  }
  imex_->rhs_explicit(t_ + dt, yp, fn, op_);
  evaluated();
  const auto& b = op_.affine();
  double *const r = rhs_.data(), *const x = guess_.data();
#pragma omp parallel
  for_each_by_particle(0, nv, L, [&](std::size_t k) {
    r[k] = y[vb + k] + 0.5 * dt * (fn[vb + k] + b[k]);
    x[k] = yp[vb + k];
  });
  solve_.solve(op_, 0.5 * dt, r, x);
#pragma omp parallel
  {
    // The trapezoidal rule for the position correction, as in leapfrog_kdk.cpp.
    for_each_by_particle(0, nv, L, [&](std::size_t k) {
      y[vb + k] = x[k];
      const double cn = fn[k] - yp[vb + k];
      y[k] += 0.5 * dt * (cn - c[k]);
      c[k] = cn;
    });
    for_each_by_particle(ve, n, L, [&](std::size_t k) { y[k] += 0.5 * dt * (f[k] + fn[k]); });
  }
  f_.swap(fnew_);
  dt_prev_ = dt;
  // f_I,n+1 = L_n+1 v_n+1 + b_n+1 for the next step, kept as state: L_n+1 was recorded at the
  // predicted state, which a restart or a migration cannot record again.
  op_.apply_affine(y + vb, w);
}

void LeapfrogImex::save_extra(nlohmann::json& j) const {
  j["v_previous"] = encode_doubles(vprev_);
  j["dt_previous"] = encode_doubles({dt_prev_});
  j["f_implicit"] = encode_doubles(w_);
  j["krylov_iterations"] = krylov_iterations();
  j["implicit_solves"] = solve_.total_solves() + solves_before_;
}

void LeapfrogImex::restore_extra(const nlohmann::json& j) {
  const auto v = decode_doubles(j.at("v_previous").get<std::string>());
  if (v.size() != vprev_.size()) throw std::runtime_error("leapfrog_imex: checkpoint state does not match this system (sizes differ)");
  vprev_ = v;
  dt_prev_ = decode_doubles(j.at("dt_previous").get<std::string>()).at(0);
  // Without it (a checkpoint of an older sph-mol) initialized() applied L, b recorded at the state.
  if (j.contains("f_implicit")) {
    const auto w = decode_doubles(j.at("f_implicit").get<std::string>());
    if (w.size() != w_.size()) throw std::runtime_error("leapfrog_imex: checkpoint state does not match this system (sizes differ)");
    w_ = w;
  }
  // The saved totals, whatever this solver counted already (a start on a new share over MPI ranks
  // restores the state saved by this same process).
  iterations_before_ = saved_count(j, "krylov_iterations") - solve_.total_iterations();
  solves_before_ = saved_count(j, "implicit_solves") - solve_.total_solves();
}

}  // namespace sphmol
