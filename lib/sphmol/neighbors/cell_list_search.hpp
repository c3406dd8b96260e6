#pragma once
// Cell linked list (Niedoba 2012, §2.2.5): particles binned into cells at least one search radius
// wide, each particle tested against the 3^D cells around its own (found once per cell, shared by
// its particles). O(N) for a bounded density; periodic directions wrap the cell index. Particles
// outside the box in a non-periodic direction are put in the edge cell, so an escaping particle
// slows the search but is never lost.
#include "sphmol/neighbors/neighbor_search.hpp"

namespace sphmol {

template <int D>
class CellListSearch final : public NeighborSearch<D> {
 public:
  std::string_view name() const override { return "cell_list"; }
  void build(const SearchInput<D>& in, PairList& out) override;
  // The rows' lengths from the same pass, storing no pair (at 1e5 particles in 3D the list and its
  // per-thread buffers were most of a rank's peak memory in the partition by pair count).
  std::vector<std::uint32_t> row_lengths(const SearchInput<D>& in) override;

 private:
  // Kept between builds so that a rebuild reuses their memory.
  std::vector<std::uint32_t> cell_start_, cell_items_, cell_of_;
  std::vector<std::vector<std::uint32_t>> count_;  // per thread: particles per cell, then its start in each cell
  std::vector<std::uint32_t> range_start_;          // particles in each thread's range of cells
  std::vector<std::uint32_t> row_at_;               // start of row i in its thread's buffer
  bool counting_ = false;                           // row_lengths(): out.offset[i + 1] = row i's length only
};

extern template class CellListSearch<1>;
extern template class CellListSearch<2>;
extern template class CellListSearch<3>;

}  // namespace sphmol
