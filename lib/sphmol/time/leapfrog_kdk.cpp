#include "sphmol/time/leapfrog_kdk.hpp"

#include "sphmol/time/particle_split.hpp"

namespace sphmol {

void LeapfrogKdk::initialized() {
  ypred_.assign(sys_->size(), 0.0);
  fnew_.assign(sys_->size(), 0.0);
}

void LeapfrogKdk::step(double dt) {
  const std::size_t vb = sys_->velocities_begin(), ve = sys_->velocities_end(), n = sys_->size();
  const std::size_t nv = ve - vb;  // positions occupy [0, nv): one per velocity component
  double* const y = y_;
  double *const yp = ypred_.data(), *const fn = fnew_.data();
  const double* const f = f_.data();
  const std::size_t L = sys_->block_length();
  // Element-wise updates split over threads by particle (time/particle_split.hpp): bit-identical for
  // any thread count. A position and its velocity are updated in the same iteration (one pass over
  // the state).
  double* const c = c_.data();
#pragma omp parallel
  {
    // Drift with v_{n+1/2} plus the position correction c_n of the latest evaluation; half kick; the
    // prediction for the evaluation at t_{n+1} is one more half kick with a_n.
    for_each_by_particle(0, nv, L, [&](std::size_t k) {
      const double vhalf = y[vb + k] + 0.5 * dt * f[vb + k];
      y[k] += dt * (vhalf + c[k]);
      yp[k] = y[k];
      y[vb + k] = vhalf;
      yp[vb + k] = vhalf + 0.5 * dt * f[vb + k];
    });
    for_each_by_particle(ve, n, L, [&](std::size_t k) { yp[k] = y[k] + dt * f[k]; });
  }
  sys_->rhs(t_ + dt, yp, fn);
  evaluated();
  // Second half kick. The drift took c_n for the whole step; the trapezoidal rule dt (c_n + c_{n+1})/2
  // is second order (dt c_n alone was first order wherever c changes in time). Without a correction
  // both are exactly 0 and the positions keep their bits.
#pragma omp parallel
  {
    for_each_by_particle(0, nv, L, [&](std::size_t k) {
      y[vb + k] += 0.5 * dt * fn[vb + k];
      const double cn = fn[k] - yp[vb + k];  // relative to the velocity it was evaluated with
      y[k] += 0.5 * dt * (cn - c[k]);
      c[k] = cn;
    });
    for_each_by_particle(ve, n, L, [&](std::size_t k) { y[k] += 0.5 * dt * (f[k] + fn[k]); });
  }
  f_.swap(fnew_);
}

}  // namespace sphmol
