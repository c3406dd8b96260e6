#pragma once
// Start-up plane Poiseuille flow: plates at y = 0 and y = l fixed, fluid at rest, body force F (per unit
// mass, along the plates) switched on at t = 0: u_t = nu u_yy + F, u(0,t) = u(l,t) = 0, u(y,0) = 0.
// Steady profile F/(2 nu) y (l - y), peak F l^2/(8 nu) at y = l/2.
//
// Vukčević et al. 2012, eq 19 (after Morris et al. 1997) prints u = F/(2nu) y(y - l) + sum
// 4Fl^2/(nu pi^3 (2n+1)^3) sin exp, which is the NEGATIVE of the solution: its steady part is < 0
// inside the channel for F > 0. Expanding y(l - y) = sum_{n odd} 8 l^2/(n^3 pi^3) sin(n pi y/l) on
// (0, l) gives the correct form
//   u = F/(2nu) y(l - y) - sum_{n>=0} 4 F l^2/(nu pi^3 (2n+1)^3) sin((2n+1) pi y/l) exp(-(2n+1)^2 pi^2 nu t/l^2),
// which vanishes at t = 0 and is > 0 for F > 0.
// velocity() is accurate to 1e-14 peak_velocity() at every t >= 0: Fourier form for nu t/l^2 >= switch_tau,
// image form (repeated erfc) below.

namespace sphmol {

struct PoiseuilleSeries {
  double l;   // plate distance [m]
  double nu;  // kinematic viscosity [m^2/s]
  double F;   // body force per unit mass [m/s^2]

  static constexpr double switch_tau = 0.02;

  // u(y, t) for 0 <= y <= l, t >= 0; t = 0 gives the initial condition 0.
  double velocity(double y, double t) const;
  double steady_velocity(double y) const;  // F/(2 nu) y (l - y)
  double peak_velocity() const;            // F l^2 / (8 nu)
  // Both representations, each summed until a rigorous tail bound is below 1e-17 peak_velocity().
  double velocity_fourier(double y, double t) const;  // requires t > 0
  double velocity_images(double y, double t) const;   // requires t > 0
};

}  // namespace sphmol
