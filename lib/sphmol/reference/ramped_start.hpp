#pragma once
// A linear flow at rest at t = 0 whose body force is ramped in over `ramp` seconds with
// body_force_ramp_factor (physics/body_force.hpp: r(t) = (1 - cos(pi t / ramp)) / 2 for t < ramp, 1
// after), from its step response u_step(t), the flow under the full force from t = 0. The forcing is
// F r(t), so by Duhamel's principle, integrated by parts with r(0) = 0 and u_step(0) = 0,
//   u(t) = int_0^min(t, ramp) r'(tau) u_step(t - tau) dtau,   r'(tau) = pi / (2 ramp) sin(pi tau / ramp),
// a smooth integrand, summed by GSL's adaptive Gauss-Kronrod quadrature to `abs_tol` (in the units of u).
// ramp <= 0: u_step(t).
#include <functional>

namespace sphmol {

double ramped_start(const std::function<double(double)>& u_step, double t, double ramp, double abs_tol);

}  // namespace sphmol
