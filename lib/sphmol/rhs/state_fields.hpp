#pragma once
// Which optional fields a scene integrates (the state holds only what the scene needs) and
// how the smoothing length evolves (Niedoba 2012, §2.2.5).
namespace sphmol {

enum class SmoothingLengthMode {
  constant,  // h fixed
  density,   // h_i = h_i(0) (rho_i(0) / rho_i)^(1/D), Niedoba 2012, eq 2.67, from the state density
  ode,       // dh_i/dt = -(h_i / (D rho_i)) drho_i/dt, Niedoba 2012, eq 2.68, h in the state
};

struct StateFields {
  bool density = false;  // continuity density (Niedoba 2012, eq 2.61): rho in the state
  bool energy = false;   // energy equation (Niedoba 2012, eq 2.66/2.72): e in the state
  SmoothingLengthMode smoothing_length = SmoothingLengthMode::constant;
  // Dynamic boundary particles (Crespo et al. 2007): wall densities in the state. The EOS and the
  // momentum equation read max(rho_wall, wall_density_floor): DualSPHysics clamps wall densities at
  // rho0 likewise, so that a wall never pulls fluid in with a negative pressure. With a width > 0 the
  // max is the smooth (C^6) one of core/polynomial_step.hpp, floor + smooth_max0(rho - floor, width): exactly
  // rho above floor + width, exactly floor at or below it (a kink in f(t, y) caps every fixed-step
  // integrator at order 2).
  bool wall_density = false;
  double wall_density_floor = 0.0;
  double wall_density_floor_width = 0.0;  // kg/m^3 (D-dimensional density units); 0 = the plain max
};

}  // namespace sphmol
