#pragma once
// Laminar flow in a rectangular duct |y| < a, |z| < b, periodic (infinitely long) in x, no-slip walls,
// driven by a body force g per unit mass along x: u_t = nu (u_yy + u_zz) + g, u = 0 on the walls.
//
// Steady profile (White 2006, eq 3-48, with -dp/dx / mu replaced by g / nu):
//   u_s = 16 a^2 g/(nu pi^3) sum_{i odd} (-1)^{(i-1)/2} [1 - cosh(i pi z/2a)/cosh(i pi b/2a)] cos(i pi y/2a)/i^3.
// The "1" part sums in closed form to the plane-channel profile g (a^2 - y^2)/(2 nu) (the cosine series of
// a^2 - y^2 on (-a, a)), leaving a remainder that converges geometrically away from the z walls; the same
// formula with (y, a) and (z, b) exchanged converges geometrically away from the y walls, and the faster
// of the two is summed.
// Mean velocity (White 2006, eq 3-49): u_m = g a^2/(3 nu) [1 - 192 a/(pi^5 b) sum_{i odd} tanh(i pi b/2a)/i^5].
//
// Start-up from rest (g switched on at t = 0, u(y, z, 0) = 0), the double Fourier series (separation of
// variables; the product of the two one-dimensional cosine series of 1 on (-a, a) and (-b, b)):
//   u = sum_{m,n odd} 16 g (-1)^{(m+n)/2-1} / (pi^2 m n nu lambda_mn) (1 - e^{-nu lambda_mn t})
//       cos(m pi y/2a) cos(n pi z/2b),   lambda_mn = (m pi/2a)^2 + (n pi/2b)^2,
// computed as u_s minus the decaying part, whose tail is bounded in closed form. For short times, where
// that series needs many terms, the Duhamel form u = g int_0^t theta_a(y, s) theta_b(z, s) ds is used:
// theta_a is the one-dimensional heat-equation solution on (-a, a) from 1 with zero walls (the product
// theta_a theta_b is the rectangle's), summed by images (erfc), and the integral by GSL's adaptive
// Gauss-Kronrod quadrature.
//
// Every sum stops when a rigorous bound on the remaining terms is below 1e-16 g c^2/nu, c = min(a, b);
// velocity() is accurate to about 1e-13 g c^2/nu (the quadrature's tolerance) at every t >= 0.

namespace sphmol {

struct DuctSeries {
  double a;   // half-width in y [m]
  double b;   // half-width in z [m]
  double nu;  // kinematic viscosity [m^2/s]
  double g;   // body force per unit mass along x [m/s^2]

  // Dimensionless time nu t / min(a, b)^2 below which velocity() uses the Duhamel form.
  static constexpr double switch_tau = 0.02;

  // u(y, z, t) for |y| <= a, |z| <= b, t >= 0 (t = 0 gives 0).
  double velocity(double y, double z, double t) const;
  double steady_velocity(double y, double z) const;
  double centre_velocity() const;  // steady u(0, 0), the largest speed
  double mean_velocity() const;    // steady flow rate / (4 a b)
  // The two transient representations; both require t > 0. Public so tests can check they agree.
  double velocity_fourier(double y, double z, double t) const;
  // velocity_duhamel (and velocity() below switch_tau) switches GSL's global error handler off while it
  // integrates: call it from one thread at a time.
  double velocity_duhamel(double y, double z, double t) const;
  // The one-dimensional start-up factor theta on (-half, half): 1 at s = 0, 0 on the walls.
  double heat_factor(double x, double half, double s) const;
};

}  // namespace sphmol
