#pragma once
// The per-particle fields an evaluation leaves for measurements and output (SphSystem::density(),
// pressure(), ...), one value per particle of the scene (fluid, then walls; generated particles not
// included), in state order. A run over ranks gathers them from the ranks' evaluations of their own
// particles and sets them on the whole system (SphSystem::set_fields), which is never evaluated.
#include <vector>

namespace sphmol {

struct ParticleFieldValues {
  std::vector<double> density, pressure, sound_speed, energy, smoothing_length;
};

}  // namespace sphmol
