#pragma once
// The decaying Arnold-Beltrami-Childress (ABC) flow on the periodic cube [0, L]^3, k = 2 pi / L:
//   u = (A sin kz + C cos ky,  B sin kx + A cos kz,  C sin ky + B cos kx) e^{-nu k^2 t},
//   p = p0 - rho |u|^2 / 2.
// An exact solution of the incompressible Navier-Stokes equations (Dombre et al. 1986, §1, for the
// steady field): u is divergence free and Beltrami, curl u = k u, so u x curl u = 0 and
// u.grad u = grad(|u|^2/2) - u x curl u = grad(|u|^2/2), balanced by the pressure above; each component is
// an eigenfunction of the Laplacian, lap u = -k^2 u, so nu lap u = u_t fixes the decay rate nu k^2.

#include <array>

namespace sphmol {

struct AbcFlow {
  double A = 1.0, B = 1.0, C = 1.0;  // mode amplitudes [m/s]
  double L = 1.0;                    // cube side [m]
  double nu = 0.01;                  // kinematic viscosity [m^2/s]
  double rho = 1.0;                  // density [kg/m^3]
  double p0 = 0.0;                   // pressure where u = 0 [Pa]

  double wavenumber() const;  // k = 2 pi / L
  double decay_rate() const;  // nu k^2 > 0: the amplitude goes as e^{-decay_rate t}
  std::array<double, 3> velocity(double x, double y, double z, double t) const;
  double pressure(double x, double y, double z, double t) const;
  // Domain integral of rho |u|^2 / 2: rho L^3 (A^2 + B^2 + C^2) e^{-2 nu k^2 t} / 2.
  double kinetic_energy(double t) const;
};

}  // namespace sphmol
