#include "sphmol/time/leapfrog.hpp"

#include <stdexcept>

#include "sphmol/io/double_codec.hpp"
#include "sphmol/time/particle_split.hpp"

namespace sphmol {

void Leapfrog::initialized() {
  const std::size_t n = sys_->size(), vb = sys_->velocities_begin(), nv = sys_->velocities_end() - vb;
  ymid_.assign(n, 0.0);
  fmid_.assign(n, 0.0);
  c_.resize(nv);
  for (std::size_t k = 0; k < nv; ++k) c_[k] = f_[k] - y_[vb + k];
}

void Leapfrog::step(double dt) {
  const std::size_t vb = sys_->velocities_begin(), ve = sys_->velocities_end(), n = sys_->size();
  const std::size_t nv = ve - vb;  // positions occupy [0, nv): one per velocity component
  double* const y = y_;
  double *const ym = ymid_.data(), *const fm = fmid_.data(), *const c = c_.data();
  const double* const f = f_.data();
  const std::size_t L = sys_->block_length();
  // Every update is element-wise, so the split over threads (by particle, time/particle_split.hpp)
  // leaves the result bit-identical for any thread count. A position and its velocity are updated in
  // the same iteration: one pass over the state per half step instead of three.
  // Half drift with v_n plus the latest XSPH correction; predicted half-step velocity; midpoint
  // prediction for other fields.
#pragma omp parallel
  {
    for_each_by_particle(0, nv, L, [&](std::size_t k) {
      ym[k] = y[k] + 0.5 * dt * (y[vb + k] + c[k]);
      ym[vb + k] = y[vb + k] + 0.5 * dt * f[vb + k];
    });
    for_each_by_particle(ve, n, L, [&](std::size_t k) { ym[k] = y[k] + 0.5 * dt * f[k]; });
  }
  sys_->rhs(t_ + 0.5 * dt, ym, fm);
  evaluated();
  // Kick, second half drift with v_{n+1}, midpoint for the rest.
#pragma omp parallel
  {
    for_each_by_particle(0, nv, L, [&](std::size_t k) {
      y[vb + k] += dt * fm[vb + k];
      c[k] = fm[k] - ym[vb + k];  // XSPH correction relative to the velocity it was evaluated with
      y[k] = ym[k] + 0.5 * dt * (y[vb + k] + c[k]);
    });
    for_each_by_particle(ve, n, L, [&](std::size_t k) { y[k] += dt * fm[k]; });
  }
  f_.swap(fmid_);
}

void Leapfrog::save_extra(nlohmann::json& j) const { j["c"] = encode_doubles(c_); }

void Leapfrog::restore_extra(const nlohmann::json& j) {
  const auto c = decode_doubles(j.at("c").get<std::string>());
  if (c.size() != c_.size()) throw std::runtime_error("leapfrog: checkpoint state does not match this system (sizes differ)");
  c_ = c;
}

}  // namespace sphmol
