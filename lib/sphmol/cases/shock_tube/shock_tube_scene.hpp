#pragma once
// The shock tube: fluid filling x in [-L/2, L/2] (2D: y in [0, W]), diaphragm at x = 0.
// shock_tube.setup chooses how the density jump is carried:
//   equal_mass (default): every particle has the mass m = rho_dense dx^D of the denser side's
//     lattice (spacing dx); the lighter side's particles lie (rho_dense / rho_light)^(1/D) dx apart,
//     so the particle spacing, not the mass, carries the jump (the shock-tube setup of Monaghan 1997 and Price 2008).
//     In 2D the lighter side has the whole number of rows across W nearest to W / (that spacing), and
//     its column spacing makes the mass exactly m.
//   equal_spacing: one square lattice of spacing dx on both sides, m = rho dx^D with the left or right
//     density (Niedoba 2012, §3.2).
// Columns are laid out from the diaphragm outwards, each one as wide as its mass needs at the local
// density; with shock_tube.smoothing = w > 0 that density (and the pressure) follows
//   q(x) = q_L + (q_R - q_L) / (1 + exp(-x / (w dx)))
// instead of a step (a smoothed initial discontinuity; with equal_spacing the masses follow it).
// Every particle's h0 is smoothing_ratio (m / rho)^(1/D).
// y walls follow discretization.boundary (2D only):
//   ghost: free-slip mirror walls at y = 0 and y = W (Niedoba 2012, §3.2-3.3, eqs 2.77-2.78; `walls`);
//   virtual_repulsive: fixed virtual particles on y = -dx and y = W + dx at spacing dx/2 (Niedoba 2012, §3.3,
//     Fig 3.3) with the repulsive force of eq 2.76 and, as in the textbook code, mass rho dx^2;
//   wall_particles: y periodic, physically the same as free-slip walls for this 1D problem (no flow
//     across y, no y-gradients), without any wall error.
// The x ends are closed by `wall_layers` layers of
// fixed wall particles continuing the lattice and holding the initial state of their side; the
// waves do not reach them by t = 0.2 (fastest: rarefaction head at x = -c_L t = -0.24, shock at
// about +0.31), so they only keep the end particles from expanding into vacuum.
#include <array>
#include <vector>

#include "sphmol/boundary/ghost_particles.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"

namespace sphmol {

template <int D>
struct ShockTubeScene {
  Particles<D> particles;
  Domain<D> domain;
  std::vector<double> energy;  // initial specific internal energy, all particles
  std::vector<double> h0;      // initial smoothing length, all particles
  BoxWalls<D> walls{};         // the ghost walls (only y, only with boundary: ghost)
  double spacing = 0.0;
  int columns = 0, rows = 1, wall_layers = 0;
  std::array<int, 2> side_rows{1, 1};  // rows across the tube of the left and right gas (2D)
};

template <int D>
ShockTubeScene<D> build_shock_tube_scene(const Config& config);

}  // namespace sphmol
