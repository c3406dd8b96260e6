#pragma once
// Error weights for an adaptive integrator on an SPH state y = [positions | velocities | other
// fields], each position and velocity component one block of block_length() entries
// (time/ode_system.hpp). The usual weight 1 / (rtol |y_i| + atol) with a scalar atol measures a
// component that is zero but for noise (the cross-stream velocity of a channel flow, a coordinate
// near the origin) against atol alone: the step-size test and the stage solves then resolve noise far
// below the flow's own accuracy. Here each component is measured against its block's scale S as well,
//   w_i = 1 / (rtol (|y_i| + S_b) + atol),
// S_b = the fluid's extent (largest max - min over the position components) for positions, the
// largest |v| over all velocity components for velocities, 0 for the other fields (densities are far
// from zero). S is taken from the state the weights are set for (the step's start), so the weights are
// a function of that state alone; a state at rest (S = 0) falls back to atol.
// Over MPI ranks S is the whole state's: the extremes are reduced over the ranks (minima and maxima
// are exact in any order), so every rank weighs its entries as the serial run does.
#include <cstddef>
#include <functional>

namespace sphmol {

struct StateBlocks {
  std::size_t size = 0, velocities_begin = 0, velocities_end = 0;
  std::size_t block = 0;  // entries per position or velocity component block
};

// Replaces `count` values by their minima over every process (collective); empty: one process.
using MinimumOverProcesses = std::function<void(double* values, std::size_t count)>;

// w (length blocks.size) from y; at most 3 position blocks.
void block_error_weights(const StateBlocks& blocks, double rtol, double atol, const double* y, double* w,
                         const MinimumOverProcesses& minimum = {});

}  // namespace sphmol
