#include "sphmol/time/leapfrog_kdk.hpp"

namespace sphmol {

void LeapfrogKdk::initialized() {
  ypred_.assign(sys_->size(), 0.0);
  fnew_.assign(sys_->size(), 0.0);
}

void LeapfrogKdk::step(double dt) {
  const std::size_t vb = sys_->velocities_begin(), ve = sys_->velocities_end(), n = sys_->size();
  const std::size_t nv = ve - vb;  // positions occupy [0, nv): one per velocity component
  double* y = y_;
  // Drift with v_{n+1/2} plus the XSPH correction c_n = f_pos - v_n of the latest evaluation.
  for (std::size_t k = 0; k < nv; ++k) {
    const double c = f_[k] - y[vb + k];
    const double vhalf = y[vb + k] + 0.5 * dt * f_[vb + k];
    y[k] += dt * (vhalf + c);
  }
  // Half kick; the prediction for the evaluation at t_{n+1} is one more half kick with a_n.
  for (std::size_t k = 0; k < nv; ++k) ypred_[k] = y[k];
  for (std::size_t k = vb; k < ve; ++k) {
    y[k] += 0.5 * dt * f_[k];
    ypred_[k] = y[k] + 0.5 * dt * f_[k];
  }
  for (std::size_t k = ve; k < n; ++k) ypred_[k] = y[k] + dt * f_[k];
  sys_->rhs(t_ + dt, ypred_.data(), fnew_.data());
  evaluated();
  for (std::size_t k = vb; k < ve; ++k) y[k] += 0.5 * dt * fnew_[k];
  for (std::size_t k = ve; k < n; ++k) y[k] += 0.5 * dt * (f_[k] + fnew_[k]);
  f_.swap(fnew_);
}

}  // namespace sphmol
