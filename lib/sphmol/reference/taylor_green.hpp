#pragma once
// Decaying Taylor-Green vortex on the periodic unit square (L = 1), exact for the incompressible
// Navier-Stokes equations:
//   u = -U e^{bt} cos(2 pi x) sin(2 pi y),  v = U e^{bt} sin(2 pi x) cos(2 pi y),
//   p = -rho U^2 e^{2bt} (cos 4 pi x + cos 4 pi y) / 4,  b = -8 pi^2 nu / L^2,  nu = U L / Re.
// (b = -8 pi^2 / Re for U = L = 1.) Derivation: u.grad u = (-pi U^2 e^{2bt} sin 4 pi x, -pi U^2 e^{2bt} sin 4 pi y)
// = -grad p / rho fixes the pressure sign (p is lowest at the vortex centres, as it must be); the
// viscous term nu lap u = -8 pi^2 nu u balances u_t = b u.

namespace sphmol {

struct TaylorGreenVortex {
  double U = 1.0;     // velocity amplitude [m/s]
  double Re = 100.0;  // Reynolds number U L / nu with L = 1
  double rho = 1.0;   // density [kg/m^3]

  double nu() const { return U / Re; }
  double decay_rate() const;  // b (negative)
  double u(double x, double y, double t) const;
  double v(double x, double y, double t) const;
  double pressure(double x, double y, double t) const;
  double kinetic_energy(double t) const;  // domain integral of rho |u|^2 / 2 = rho U^2 e^{2bt} / 4
};

}  // namespace sphmol
