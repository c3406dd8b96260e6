#pragma once
// One interface for every neighbour search (all-pairs reference, CGAL kd-tree, ...).
#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"
#include "sphmol/neighbors/pair_list.hpp"

namespace sphmol {

template <int D>
struct SearchInput {
  std::array<const double*, D> x{};  // positions, inside the domain in periodic directions
  const Kind* kind = nullptr;
  std::size_t n = 0;
  const Domain<D>* domain = nullptr;
  double radius = 0.0;
};

template <int D>
class NeighborSearch {
 public:
  virtual ~NeighborSearch() = default;
  virtual std::string_view name() const = 0;
  virtual void build(const SearchInput<D>& in, PairList& out) = 0;
};

// "kdtree", "cell_list" or "all_pairs".
template <int D>
std::unique_ptr<NeighborSearch<D>> make_neighbor_search(std::string_view name);

namespace detail {
// Shared pair predicate of every search, so all of them give identical pair sets.
template <int D>
inline bool is_pair(const SearchInput<D>& in, std::size_t i, std::size_t j) {
  if (i == j) return false;
  if (in.kind[i] != Kind::Fluid && in.kind[j] != Kind::Fluid) return false;
  double r2 = 0.0;
  for (int d = 0; d < D; ++d) {
    const double dx = in.domain->min_image(d, in.x[d][i] - in.x[d][j]);
    r2 += dx * dx;
  }
  return r2 < in.radius * in.radius;
}
}  // namespace detail

}  // namespace sphmol
