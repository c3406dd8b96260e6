#pragma once
// A rectangular 2D box [0, Lx] x [0, Ly] filled with fluid on the square lattice ((i+1/2) dx, (j+1/2) dx)
// up to a fluid height, with planar walls on any of its four faces (or periodic, for Taylor-Green).
// How the walls are represented follows discretization.boundary:
//   wall_particles: the lattice continued outside the box in enough layers to fill the kernel support
//     (corner regions included; a corner particle belongs to the top wall if that wall is present, so
//     a moving lid spans the corners, else to the wall it lies deeper behind);
//   virtual_repulsive: one row of massless particles on each wall line at spacing dx/2 (the wall line
//     is dx/2 outside the outermost fluid particles, the placement of Niedoba 2012, Fig 3.3); they act only
//     through the repulsive force of Niedoba 2012, eq 2.76;
//   ghost: no particles here: mirror images are generated at every RHS evaluation from `walls`.
// Walls with a nonzero velocity are belts: their particles stay put and carry the velocity.
#include "sphmol/boundary/ghost_particles.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"

namespace sphmol {

struct BoxScene {
  Particles<2> particles;
  Domain<2> domain;
  BoxWalls<2> walls;
  double spacing = 0.0;
  int nx = 0, ny = 0;  // fluid lattice
  int wall_layers = 0;
};

// box = [Lx, Ly] of the walls; fluid_height <= Ly; walls[d][s].present/velocity chosen by the case
// (positions are set here: 0 and L). particles_across counts fluid particles along x.
BoxScene build_box_scene(const Config& config, double Lx, double Ly, double fluid_height, BoxWalls<2> walls,
                         bool periodic);

}  // namespace sphmol
