#pragma once
// A rectangular box [0, L_1] x ... x [0, L_D] filled with fluid on the square (cubic) lattice
// ((i+1/2) dx, (j+1/2) dx, ...) up to a fluid height along the last axis, with planar walls on any of
// its faces (or periodic, for Taylor-Green). How the walls are represented follows
// discretization.boundary:
//   wall_particles: the lattice continued outside the box in enough layers to fill the kernel support
//     (corner regions included; a corner particle belongs to the top wall if that wall is present, so
//     a moving lid spans the corners, else to the wall it lies deeper behind);
//   virtual_repulsive (2D only): one row of massless particles on each wall line at spacing dx/2 (the
//     wall line is dx/2 outside the outermost fluid particles, the placement of Niedoba 2012, Fig 3.3);
//     they act only through the repulsive force of Niedoba 2012, eq 2.76;
//   ghost: no particles here: mirror images are generated at every RHS evaluation from `walls`.
// Walls with a nonzero velocity are belts: their particles stay put and carry the velocity.
// The fluid and the wall particles come from the geometry kit (geometry/lattice.hpp fill,
// geometry/wall_layers.hpp box_container_walls).
#include <array>

#include "sphmol/boundary/ghost_particles.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"

namespace sphmol {

template <int D>
struct BoxSceneOf {
  Particles<D> particles;
  Domain<D> domain;
  BoxWalls<D> walls;
  double spacing = 0.0;
  std::array<int, D> cells{};  // fluid lattice: particles along each axis
  int wall_layers = 0;
};
using BoxScene = BoxSceneOf<2>;

// box = the lengths of the walls' box (the last one its height); fluid_height <= box[D-1];
// walls[d][s].present/velocity chosen by the case (positions are set here: 0 and box[d]).
// discretization.particles_across counts fluid particles along x.
template <int D>
BoxSceneOf<D> build_box_scene(const Config& config, const std::array<double, D>& box, double fluid_height,
                              BoxWalls<D> walls, bool periodic);

// The 2D box [0, Lx] x [0, Ly].
inline BoxScene build_box_scene(const Config& config, double Lx, double Ly, double fluid_height, BoxWalls<2> walls,
                                bool periodic) {
  return build_box_scene<2>(config, {Lx, Ly}, fluid_height, walls, periodic);
}

}  // namespace sphmol
