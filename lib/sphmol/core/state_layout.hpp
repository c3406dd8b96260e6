#pragma once
// Layout of the ODE state vector y for n fluid particles. The state holds only what a scene needs
// (no unused fields): positions and velocities always, one block per component (structure of
// arrays), then the optional first-order fields in a fixed order: density (continuity density,
// Niedoba 2012, eq 2.61), specific internal energy (energy equation, Niedoba 2012, eq 2.66),
// smoothing length (dh/dt, Niedoba 2012, eq 2.68), and last the densities of the n_wall_density
// wall particles (dynamic boundary particles, Crespo et al. 2007: walls obey continuity but do not
// move, so only their density is in the state). The SUNDIALS N_Vector wraps this storage directly.
#include <cstddef>
#include <string>
#include <vector>

namespace sphmol {

template <int D>
struct StateLayout {
  std::size_t n = 0;  // fluid particles
  bool has_density = false, has_energy = false, has_smoothing_length = false;
  std::size_t n_wall_density = 0;  // wall particles whose density is integrated (0 unless DBC)

  std::size_t extra_blocks() const {
    return static_cast<std::size_t>(has_density) + static_cast<std::size_t>(has_energy) +
           static_cast<std::size_t>(has_smoothing_length);
  }
  std::size_t size() const { return (2 * D + extra_blocks()) * n + n_wall_density; }
  std::size_t position(int d) const { return static_cast<std::size_t>(d) * n; }
  std::size_t velocity(int d) const { return static_cast<std::size_t>(D + d) * n; }
  // Offsets of the optional blocks; meaningful only when the block is present.
  std::size_t density() const { return 2 * D * n; }
  std::size_t energy() const { return (2 * D + static_cast<std::size_t>(has_density)) * n; }
  std::size_t smoothing_length() const {
    return (2 * D + static_cast<std::size_t>(has_density) + static_cast<std::size_t>(has_energy)) * n;
  }
  std::size_t wall_density() const { return (2 * D + extra_blocks()) * n; }
  // Leapfrog splits y into positions [0, D n), velocities [D n, 2 D n) and first-order fields after.
  std::size_t positions_begin() const { return 0; }
  std::size_t velocities_begin() const { return D * n; }
  std::size_t velocities_end() const { return 2 * D * n; }

  std::vector<std::string> field_names() const {
    std::vector<std::string> f{"position", "velocity"};
    if (has_density) f.emplace_back("density");
    if (has_energy) f.emplace_back("energy");
    if (has_smoothing_length) f.emplace_back("smoothing_length");
    if (n_wall_density > 0) f.emplace_back("wall_density");
    return f;
  }
};

}  // namespace sphmol
