#pragma once
// Two ghost mirrors that face each other across the fluid, `gap` apart (a channel or tube of width
// gap between mirror walls). The exact mirror image of that fluid is an infinite row of reflections;
// the ghost generator (boundary/ghost_particles.hpp) makes the first reflection through each mirror
// (and through mirrors at right angles together), not the reflection through one and then the other.
// With the fluid half a spacing dx from each mirror, those missing images lie at least gap + dx from
// every fluid particle, so they are outside the kernel support when gap + dx >= support; a narrower
// gap leaves holes in the sums near both walls (a 2D shock tube two spacings wide, Gaussian kernel
// at h = 1.3 dx, blew up at t = 0.049 s).
#include <cmath>
#include <string>

#include "sphmol/core/six_digits.hpp"

namespace sphmol {

// support: the kernel support kappa h in metres, at the scene's h.
inline bool facing_mirrors_too_close(double gap, double dx, double support) {
  return gap > 0.0 && gap + dx < support * (1.0 - 1e-9);
}

// Why, for a ConfigError at the key that sets the gap.
inline std::string facing_mirrors_message(double gap, double dx, double support) {
  const double spacings = std::ceil((support - dx) / dx * (1.0 - 1e-9));
  return "ghost walls facing each other " + six_digits(gap) + " m apart: the images of images through both walls, which the ghost "
         "boundary does not make, would lie within the kernel support of the fluid (gap + dx = " + six_digits(gap + dx) +
         " m < support " + six_digits(support) + " m). Widen the gap to at least " + six_digits(spacings) + " spacings (" +
         six_digits(spacings * dx) + " m), or use discretization.boundary: wall_particles";
}

}  // namespace sphmol
