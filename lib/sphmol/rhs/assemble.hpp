#pragma once
// Builds the RHS of a scene from the configuration, once: the kernel pass, the neighbour search
// with its skin, and the ordered list of terms (density -> EOS -> strain rate -> accelerations ->
// position update). Nothing configured off is in the list. `energy`: initial e of every particle,
// for scenes with the energy equation.
#include <memory>
#include <vector>

#include "sphmol/boundary/ghost_particles.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/rhs/sph_system.hpp"

namespace sphmol {

template <int D>
std::unique_ptr<SphSystem<D>> assemble_system(const Config& config, Particles<D> particles, const Domain<D>& domain,
                                              double spacing, const BoxWalls<D>* walls = nullptr,
                                              std::vector<double> energy = {}, const std::vector<GhostPlane<D>>& planes = {});
// `walls`: the scene's planar walls, needed by boundary: ghost (mirror images are generated from them);
// `planes`: further mirror planes (a scene's ghost wall bodies), with boundary: ghost only.
// `energy`: initial specific internal energy per particle, for scenes with the energy equation.

}  // namespace sphmol
