#pragma once
// One interface for every neighbour search (all-pairs reference, CGAL kd-tree, ...).
#include <array>
#include <cmath>
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
  // The length of every row of the list build() makes (each particle's pair count), without keeping
  // the pairs: what a partition by pair count weighs particles by. Default: build() and the offsets.
  virtual std::vector<std::uint32_t> row_lengths(const SearchInput<D>& in) {
    PairList list;
    build(in, list);
    std::vector<std::uint32_t> len(in.n);
    for (std::size_t i = 0; i < in.n; ++i) len[i] = static_cast<std::uint32_t>(list.offset[i + 1] - list.offset[i]);
    return len;
  }
};

// "kdtree", "cell_list" or "all_pairs".
template <int D>
std::unique_ptr<NeighborSearch<D>> make_neighbor_search(std::string_view name);

namespace detail {
// Pairs of two boundary particles are never listed, nor any pair with a particle taken out
// (Kind::Out, core/particles.hpp).
inline bool listable(Kind a, Kind b) {
  return (a == Kind::Fluid || b == Kind::Fluid) && a != Kind::Out && b != Kind::Out;
}

// Shared pair predicate of every search, so all of them give identical pair sets. It takes the box
// constants once per build, and the distance test (within) also applies to coordinates a search has
// copied; the arithmetic is Domain::min_image's.
template <int D>
struct PairDistance {
  std::array<double, D> period{}, inv_period{};
  double radius2 = 0.0;
  explicit PairDistance(const SearchInput<D>& in) : radius2(in.radius * in.radius) {
    for (int d = 0; d < D; ++d) {
      period[d] = in.domain->period(d);
      inv_period[d] = in.domain->inv_period(d);
    }
  }
  // dx[d] = x_i - x_j per direction.
  bool within(const std::array<double, D>& dx) const {
    double r2 = 0.0;
    for (int d = 0; d < D; ++d) {
      const double m = dx[d] - period[d] * std::nearbyint(dx[d] * inv_period[d]);
      r2 += m * m;
    }
    return r2 < radius2;
  }
  // Particles i and j of `in` (the input this predicate was made from) form a listed pair.
  bool is_pair(const SearchInput<D>& in, std::size_t i, std::size_t j) const {
    if (i == j || !listable(in.kind[i], in.kind[j])) return false;
    std::array<double, D> dx;
    for (int d = 0; d < D; ++d) dx[d] = in.x[d][i] - in.x[d][j];
    return within(dx);
  }
};
}  // namespace detail

}  // namespace sphmol
