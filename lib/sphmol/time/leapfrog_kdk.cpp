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
#pragma omp parallel
  {
    // Drift with v_{n+1/2} plus the XSPH correction c_n = f_pos - v_n of the latest evaluation;
    // half kick; the prediction for the evaluation at t_{n+1} is one more half kick with a_n.
    for_each_by_particle(0, nv, L, [&](std::size_t k) {
      const double c = f[k] - y[vb + k];
      const double vhalf = y[vb + k] + 0.5 * dt * f[vb + k];
      y[k] += dt * (vhalf + c);
      yp[k] = y[k];
      y[vb + k] += 0.5 * dt * f[vb + k];
      yp[vb + k] = y[vb + k] + 0.5 * dt * f[vb + k];
    });
    for_each_by_particle(ve, n, L, [&](std::size_t k) { yp[k] = y[k] + dt * f[k]; });
  }
  sys_->rhs(t_ + dt, yp, fn);
  evaluated();
#pragma omp parallel
  {
    for_each_by_particle(vb, ve, L, [&](std::size_t k) { y[k] += 0.5 * dt * fn[k]; });
    for_each_by_particle(ve, n, L, [&](std::size_t k) { y[k] += 0.5 * dt * (f[k] + fn[k]); });
  }
  f_.swap(fnew_);
}

}  // namespace sphmol
