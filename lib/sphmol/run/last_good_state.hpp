#pragma once
// Writes the fluid particles of a state as CSV (particle, x0.., v0..): the last good state of a
// run that blew up, so the failure can be inspected.
#include <string>

#include "sphmol/rhs/sph_system.hpp"

namespace sphmol {

template <int D>
void write_last_good_state(const SphSystem<D>& sys, const double* y, const std::string& path);

}  // namespace sphmol
