#pragma once
// The velocity scale U of a user scene: the free-fall speed sqrt(2 |g| H) over the fluid's height H
// against the body force, or the largest initial fluid or wall speed, whichever is larger. The
// scene case reports its errors against it; a repulsive wall body takes D = U^2 by default.
#include <vector>

#include "sphmol/core/particles.hpp"

namespace sphmol {

template <int D>
double scene_velocity_scale(const Particles<D>& p, const std::vector<double>& body_force, double spacing);

}  // namespace sphmol
