#pragma once
// A system's state read from two places, its rates written to one (SphSystem::rhs_split): the rows
// the system owns live in the integrator's state (layout `owned`, the system's blocks over the
// owned rows), every other row in a buffer of rows of `width` values each (a fluid particle's value
// in each block of the state, a wall's integrated density in the first entry), as a halo exchange
// receives them. The gather reads each of the system's rows from its source and the scatter writes
// the owned rows' rates into the integrator's rates: no assembled copy of the state or of the rates.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sphmol/core/state_layout.hpp"

namespace sphmol {

template <int D>
struct SplitState {
  StateLayout<D> owned;   // the owned rows' layout (n: owned fluid rows; n_wall_density: owned walls')
  std::size_t width = 0;  // values per row of the other buffer
  // Per fluid row of the system: an owned fluid row s < owned.n, or row s - owned.n of the buffer.
  std::vector<std::uint32_t> fluid_source;
  // Per wall-density row of the system: an owned wall-density row s < owned.n_wall_density, or row
  // s - owned.n_wall_density of the buffer.
  std::vector<std::uint32_t> wall_source;
  // Per owned fluid row and per owned wall-density row: the system's row whose rates it takes.
  std::vector<std::uint32_t> fluid_rate_row, wall_rate_row;
};

}  // namespace sphmol
