#pragma once
// Layout of the ODE state vector y for n fluid particles. The state holds only what a scene needs
// (SPEC §1): positions and velocities always, one block per component (structure of arrays), then
// optional blocks. The SUNDIALS N_Vector wraps this storage directly.
#include <cstddef>
#include <string>
#include <vector>

namespace sphmol {

template <int D>
struct StateLayout {
  std::size_t n = 0;  // fluid particles

  std::size_t size() const { return 2 * D * n; }
  std::size_t position(int d) const { return static_cast<std::size_t>(d) * n; }
  std::size_t velocity(int d) const { return static_cast<std::size_t>(D + d) * n; }
  // Leapfrog splits y into positions [0, D n) and velocities [D n, 2 D n).
  std::size_t positions_begin() const { return 0; }
  std::size_t velocities_begin() const { return D * n; }
  std::size_t velocities_end() const { return 2 * D * n; }

  std::vector<std::string> field_names() const { return {"position", "velocity"}; }
};

}  // namespace sphmol
