#pragma once
// discretization.position_correction: auto -- which particle-arrangement correction a run takes, the
// transport velocity (Adami, Hu & Adams 2013; physics/transport_velocity.hpp) or Fickian particle
// shifting (Lind et al. 2012, A = 4 of Sun et al. 2017; physics/particle_shifting.hpp), chosen by
// the cell Reynolds number Re_h = U h / nu.
//
// Why Re_h: both corrections move particles by a velocity of order U on the kernel scale h, and what
// they add to the momentum budget damps the flow like a numerical diffusivity of order U h; its share
// of the physical decay nu k^2 grows with U h / nu = Re_h. Measured on the Taylor-Green vortex at 30,
// 50 and 80 particles across (docs/verification.md, "Taylor-Green over Re"), the transport velocity's
// decay-rate error collapses on Re_h (1-1.4 % at Re_h 7.5-10, 2-3 % at 12-13, 6-7 % at 20-25, 13 % at
// 40), while particle shifting has a smaller damping but a viscous deficit at small Re_h that shrinks
// with resolution (2.1 / 1.0 / 0.4 % at Re 100 for 30 / 50 / 80 across). The two errors cross at
// Re_h = 11 (30 across), 7.2 (50) and about 3.4 (80); the threshold is the top of that band, so that
// shifting is the better scheme at every measured point from the threshold on, and below it the
// transport velocity is the better one or at most 1.3 % behind (80 across, Re_h 7.5).
#include <string>

namespace sphmol {

// Below this cell Reynolds number auto takes the transport velocity, at or above it particle shifting.
inline constexpr double kPositionCorrectionCellReynolds = 12.0;

// Re_h = U h / nu; +infinity for an inviscid fluid (nu = 0).
double cell_reynolds_number(double velocity_scale, double smoothing_length, double kinematic_viscosity);

// "transport_velocity" below kPositionCorrectionCellReynolds, "particle_shifting" at or above it.
std::string position_correction_for(double cell_reynolds);

}  // namespace sphmol
