#pragma once
// Particles generated from the current state at every RHS evaluation (ghost/mirror particles,
// Niedoba 2012, §2.2.4 and §3.3). SphSystem calls the generator right after gathering positions and
// velocities, before the neighbour update. The generator appends its particles after the scene's
// own fluid + wall particles (as wall-kind particles, so they are integrated by nobody and
// ghost-ghost or ghost-wall pairs are never listed), sets their x and v in the workspace, resizes
// every per-particle array and sets w.n. Their density/pressure are copied later by a term.
#include <cstddef>

#include "sphmol/core/particles.hpp"
#include "sphmol/rhs/workspace.hpp"

namespace sphmol {

template <int D>
class ParticleGenerator {
 public:
  virtual ~ParticleGenerator() = default;
  // Returns true when the generated set differs from the previous call's (then the Verlet list is
  // rebuilt: its pairs refer to particle indices).
  virtual bool generate(std::size_t n_base, Particles<D>& particles, Workspace<D>& w) = 0;
  virtual std::size_t count() const = 0;
  // The largest speed of the walls the generated particles stand for (the work they can do on the fluid).
  virtual double max_wall_speed() const { return 0.0; }
};

}  // namespace sphmol
