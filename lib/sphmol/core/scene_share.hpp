#pragma once
// Which part of a scene a build keeps: share `index` of `count` equal shares of the global indices,
// [N index / count, N (index + 1) / count) of the N particles (fluid first). A run over MPI ranks
// starts each rank from the same slice (parallel/distributed_system.hpp), so a rank that builds its
// share (Case::build_share) holds exactly the particles it starts with. The default keeps the whole
// scene.
#include <cstddef>

namespace sphmol {

struct SceneShare {
  std::size_t index = 0, count = 1;
  // The first global index of the share of a scene of n particles, and the one past its last.
  std::size_t begin(std::size_t n) const { return n * index / count; }
  std::size_t end(std::size_t n) const { return n * (index + 1) / count; }
};

}  // namespace sphmol
