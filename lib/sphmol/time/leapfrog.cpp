#include "sphmol/time/leapfrog.hpp"

#include "sphmol/time/particle_split.hpp"

namespace sphmol {

void Leapfrog::initialized() {
  const std::size_t n = sys_->size();
  ymid_.assign(n, 0.0);
  fmid_.assign(n, 0.0);
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
  // Half drift with v_n plus the latest position correction (a prediction: its lag is taken back
  // after the midpoint evaluation); predicted half-step velocity; midpoint prediction for other fields.
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
  // Kick, second half drift with v_{n+1}, midpoint for the rest. The position correction c (XSPH,
  // transport velocity) is integrated with its midpoint value over the whole step: x_{n+1} = x_n +
  // dt (v_n + v_{n+1})/2 + dt c_{n+1/2}. The first half drift could only use the previous step's
  // c_{n-1/2}; its lag is taken back here (the last term). Leaving it in made the position update
  // dt c(t_n) instead of dt c(t_{n+1/2}): first order in time wherever c is not zero. Without a
  // correction both c are exactly 0 and the update is the plain drift-kick-drift, bit for bit.
#pragma omp parallel
  {
    for_each_by_particle(0, nv, L, [&](std::size_t k) {
      y[vb + k] += dt * fm[vb + k];
      const double cn = fm[k] - ym[vb + k];  // correction relative to the velocity it was evaluated with
      y[k] = ym[k] + 0.5 * dt * (y[vb + k] + cn) + 0.5 * dt * (cn - c[k]);
      c[k] = cn;
    });
    for_each_by_particle(ve, n, L, [&](std::size_t k) { y[k] += dt * fm[k]; });
  }
  f_.swap(fmid_);
}

}  // namespace sphmol
