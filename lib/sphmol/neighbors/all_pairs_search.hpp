#pragma once
// O(N^2) reference search: every pair tested. Used to check the fast searches.
#include "sphmol/neighbors/neighbor_search.hpp"

namespace sphmol {

template <int D>
class AllPairsSearch final : public NeighborSearch<D> {
 public:
  std::string_view name() const override { return "all_pairs"; }
  void build(const SearchInput<D>& in, PairList& out) override {
    in.domain->require_pair_radius(in.radius);
    out.clear(in.n);
    const detail::PairDistance<D> pd(in);
    for (std::size_t i = 0; i < in.n; ++i) {
      for (std::size_t j = 0; j < in.n; ++j)
        if (pd.is_pair(in, i, j)) out.j.push_back(static_cast<std::uint32_t>(j));
      out.offset[i + 1] = static_cast<std::uint32_t>(out.j.size());
    }
  }
};

}  // namespace sphmol
