#pragma once
// The 2D shock tube of Niedoba 2012, §3.2: fluid on a square lattice of spacing dx filling
// x in [-L/2, L/2], y in [0, W], diaphragm at x = 0. Following the thesis (equal spacing on both
// sides), the particle masses carry the density jump: m = rho dx^D with the left or right density.
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
  BoxWalls<D> walls{};         // the ghost walls (only y, only with boundary: ghost)
  double spacing = 0.0;
  int columns = 0, rows = 1, wall_layers = 0;
};

template <int D>
ShockTubeScene<D> build_shock_tube_scene(const Config& config);

}  // namespace sphmol
