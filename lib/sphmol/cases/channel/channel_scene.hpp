#pragma once
// Plane channel between walls at y = 0 and y = l, periodic in x over channel_length (Vukčević et al. 2012, §4):
// fluid on a square lattice at ((i+1/2) dx, (j+1/2) dx); wall particles continue the lattice
// outside, in enough layers to fill the kernel support. The top wall moves with wall_velocity.
#include "sphmol/config/config.hpp"
#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"

namespace sphmol {

struct ChannelScene {
  Particles<2> particles;
  Domain<2> domain;
  double spacing = 0.0;
  int wall_layers = 0;
};

ChannelScene build_channel_scene(const Config& config);

}  // namespace sphmol
