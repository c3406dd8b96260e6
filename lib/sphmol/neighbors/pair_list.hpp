#pragma once
// Neighbour pairs in compressed-row form: row i lists every j with |x_i - x_j| < radius
// (minimum image in periodic directions), j != i, sorted ascending. Pairs of two boundary
// particles are never listed: boundary rows hold only fluid neighbours.
#include <cstdint>
#include <vector>

namespace sphmol {

struct PairList {
  std::vector<std::uint32_t> offset{0};  // size rows + 1
  std::vector<std::uint32_t> j;

  std::size_t rows() const { return offset.size() - 1; }
  std::size_t pairs() const { return j.size(); }
  void clear(std::size_t rows) {
    offset.assign(rows + 1, 0);
    j.clear();
  }
};

}  // namespace sphmol
