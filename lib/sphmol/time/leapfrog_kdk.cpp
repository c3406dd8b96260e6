#include "sphmol/time/leapfrog_kdk.hpp"

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
  // Element-wise updates split statically over threads: bit-identical for any thread count. A
  // position and its velocity are updated in the same iteration (one pass over the state).
#pragma omp parallel
  {
    // Drift with v_{n+1/2} plus the XSPH correction c_n = f_pos - v_n of the latest evaluation;
    // half kick; the prediction for the evaluation at t_{n+1} is one more half kick with a_n.
#pragma omp for schedule(static) nowait
    for (std::size_t k = 0; k < nv; ++k) {
      const double c = f[k] - y[vb + k];
      const double vhalf = y[vb + k] + 0.5 * dt * f[vb + k];
      y[k] += dt * (vhalf + c);
      yp[k] = y[k];
      y[vb + k] += 0.5 * dt * f[vb + k];
      yp[vb + k] = y[vb + k] + 0.5 * dt * f[vb + k];
    }
#pragma omp for schedule(static) nowait
    for (std::size_t k = ve; k < n; ++k) yp[k] = y[k] + dt * f[k];
  }
  sys_->rhs(t_ + dt, yp, fn);
  evaluated();
#pragma omp parallel
  {
#pragma omp for schedule(static) nowait
    for (std::size_t k = vb; k < ve; ++k) y[k] += 0.5 * dt * fn[k];
#pragma omp for schedule(static) nowait
    for (std::size_t k = ve; k < n; ++k) y[k] += 0.5 * dt * (f[k] + fn[k]);
  }
  f_.swap(fnew_);
}

}  // namespace sphmol
