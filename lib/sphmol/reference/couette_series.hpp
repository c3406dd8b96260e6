#pragma once
// Start-up Couette flow: plate y = 0 fixed, plate y = l moves at v0 from t = 0, fluid at rest at t = 0.
// u_t = nu u_yy, u(0,t) = 0, u(l,t) = v0, u(y,0) = 0 (Vukčević et al. 2012, eq 23, Morris et al.
// 1997). velocity() is accurate to 1e-14 v0 at every t >= 0: the Fourier series (Vukčević et al.
// 2012, eq 23) for nu t / l^2 >= switch_tau, the image (erfc) series below it, where the Fourier
// series converges slowly.

namespace sphmol {

struct CouetteSeries {
  double l;   // plate distance [m]
  double nu;  // kinematic viscosity [m^2/s]
  double v0;  // speed of the upper plate [m/s]

  // Dimensionless time nu t / l^2 at which velocity() switches from the image to the Fourier form.
  static constexpr double switch_tau = 0.02;

  // u(y, t) for 0 <= y <= l, t >= 0; t = 0 gives the initial condition (0 inside, v0 on the moving plate).
  double velocity(double y, double t) const;
  // Steady profile v0 y / l.
  double steady_velocity(double y) const;
  // The two representations, each summed until a rigorous bound on the remaining tail is below 1e-17 v0.
  // Public so tests can check they agree where both converge.
  double velocity_fourier(double y, double t) const;  // requires t > 0
  double velocity_images(double y, double t) const;   // requires t > 0
};

}  // namespace sphmol
