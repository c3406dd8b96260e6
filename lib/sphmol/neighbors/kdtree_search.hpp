#pragma once
// Fixed-radius neighbour search with a CGAL kd-tree (Niedoba 2012, §2.2.5, "tree method"). Periodic
// directions are handled by inserting images of the particles within `radius` of a periodic face.
#include "sphmol/neighbors/neighbor_search.hpp"

namespace sphmol {

template <int D>
class KdTreeSearch final : public NeighborSearch<D> {
 public:
  std::string_view name() const override { return "kdtree"; }
  void build(const SearchInput<D>& in, PairList& out) override;
};

extern template class KdTreeSearch<1>;
extern template class KdTreeSearch<2>;
extern template class KdTreeSearch<3>;

}  // namespace sphmol
