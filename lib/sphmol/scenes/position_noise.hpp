#pragma once
// Seeded random displacement of the initial fluid lattice (discretization.position_noise). A perfect
// Cartesian lattice is mirror-symmetric about the lines through the stagnation points of a Taylor-Green
// vortex; the flow keeps that symmetry, so the lattice is stretched into rows that no position
// correction can break up (every particle's kernel sum stays symmetric) until they fail all at once.
// A small displacement (~1 % of the spacing) breaks the symmetry, and the transport velocity
// (physics/transport_velocity.hpp) then keeps the arrangement isotropic. The seed is fixed, so runs
// are reproducible.
#include <array>
#include <random>

#include "sphmol/core/particles.hpp"

namespace sphmol {

// The displacements in the order the fluid particles take them: displace() moves one particle by
// amplitude * U(-1, 1) in each direction, the next draws of one seeded sequence, so that a build that
// keeps only part of the scene gives each particle it keeps the displacement of the whole build.
template <int D>
class PositionNoise {
 public:
  explicit PositionNoise(double amplitude, unsigned seed = 20130301u) : amplitude_(amplitude), rng_(seed) {}
  void displace(std::array<double, D>& x) {
    if (amplitude_ <= 0.0) return;
    for (int d = 0; d < D; ++d) x[d] += amplitude_ * u_(rng_);
  }

 private:
  double amplitude_;
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> u_{-1.0, 1.0};
};

// Displaces every fluid particle by amplitude * U(-1, 1) in each direction (x and x_ref alike).
template <int D>
void add_position_noise(Particles<D>& p, double amplitude, unsigned seed = 20130301u) {
  if (amplitude <= 0.0) return;
  PositionNoise<D> noise(amplitude, seed);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.kind[i] != Kind::Fluid) continue;
    std::array<double, D> x;
    for (int d = 0; d < D; ++d) x[d] = p.x[d][i];
    noise.displace(x);
    for (int d = 0; d < D; ++d) p.x[d][i] = p.x_ref[d][i] = x[d];
  }
}

}  // namespace sphmol
