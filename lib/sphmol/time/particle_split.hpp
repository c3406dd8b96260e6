#pragma once
// Element-wise loops over a state vector y = [block 0 | block 1 | ... | tail], each block holding one
// entry per particle (OdeSystem::block_length), split over threads by particle: entry i of every block
// goes to the thread that the RHS's static loops over particles give particle i. A particle's cache
// lines then stay on the core that last wrote them; the plain static split of the whole vector gave
// one thread all x components and the other all y components, so every step moved half the state
// between the cores (on this VM's two cores, a remote line costs several times a local one). The
// tail after the last whole block (the wall densities) is split on its own. Call inside a parallel
// region; the loops end without a barrier.
#include <cstddef>

namespace sphmol {

template <class F>
void for_each_by_particle(std::size_t lo, std::size_t hi, std::size_t block, F&& f) {
  const std::size_t blocks = block > 0 ? (hi - lo) / block : 0;
  // Same trip count, schedule(static): OpenMP gives every one of these loops the same split.
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t base = lo + b * block;
#pragma omp for schedule(static) nowait
    for (std::size_t i = 0; i < block; ++i) f(base + i);
  }
#pragma omp for schedule(static) nowait
  for (std::size_t k = lo + blocks * block; k < hi; ++k) f(k);
}

}  // namespace sphmol
