#pragma once
// 2D dam break: a water column [0, a] x [0, H] (geometry.column) at the left end of an open tank
// [0, Lx] x [0, Ly] (geometry.box), on the square lattice ((i+1/2) dx, (j+1/2) dx). Walls left, right
// and below, as wall particles on the lattice continued outside the tank (discretization.wall_layers
// layers; the DualSPHysics comparison uses one), the side walls up to the tank height; open top.
// Particle mass m = rho0 dx^2 (continuity density: the volume of a lattice cell). The column starts in
// hydrostatic equilibrium: rho from the EOS inverted at p = rho0 g (H - y), as DualSPHysics does;
// wall particles next to and under the column get the hydrostatic density of their height too (others
// rho0), so dynamic walls start holding the column up instead of first being compressed by it.
#include "sphmol/config/config.hpp"
#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"

namespace sphmol {

struct DamBreakScene {
  Particles<2> particles;
  Domain<2> domain;
  double spacing = 0.0;
  int wall_layers = 0;
  double g = 0.0;  // gravity magnitude (fluid.body_force = [0, -g])
};

DamBreakScene build_dam_break_scene(const Config& config);

}  // namespace sphmol
