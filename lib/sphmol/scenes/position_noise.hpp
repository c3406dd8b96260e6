#pragma once
// Seeded random displacement of the initial fluid lattice (discretization.position_noise). A perfect
// Cartesian lattice is mirror-symmetric about the lines through the stagnation points of a Taylor-Green
// vortex; the flow keeps that symmetry, so the lattice is stretched into rows that no position
// correction can break up (every particle's kernel sum stays symmetric) until they fail all at once.
// A small displacement (~1 % of the spacing) breaks the symmetry, and the transport velocity
// (physics/transport_velocity.hpp) then keeps the arrangement isotropic. The seed is fixed, so runs
// are reproducible.
#include <random>

#include "sphmol/core/particles.hpp"

namespace sphmol {

// Displaces every fluid particle by amplitude * U(-1, 1) in each direction (x and x_ref alike).
template <int D>
void add_position_noise(Particles<D>& p, double amplitude, unsigned seed = 20130301u) {
  if (amplitude <= 0.0) return;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != Kind::Fluid) continue;
    for (int d = 0; d < D; ++d) {
      p.x[d][i] += amplitude * u(rng);
      p.x_ref[d][i] = p.x[d][i];
    }
  }
}

}  // namespace sphmol
