#pragma once
// Particle order for memory locality: particles sorted along a Morton (Z-order) curve through a grid
// of cells, so that particles close in space are close in memory and the pair loops of the RHS read
// neighbour data from cache instead of from all over the arrays. SphSystem applies the order to its
// workspace index only (the ODE state keeps its order; rhs/sph_system.cpp), each time the Verlet list
// is rebuilt. Within a cell particles are in the order of a tie key the caller gives (SphSystem: the
// state index), so the order is a pure function of the positions at the rebuild (never of the
// thread count, nor of earlier orders): a run over MPI ranks orders its local systems alike from
// each particle's global id and its position at the rebuild (parallel/distributed_system.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "sphmol/core/domain.hpp"

namespace sphmol {

namespace detail {
// Spreads the low 21 bits of v so that D interleaved codes fit 63 bits (D <= 3).
template <int D>
inline std::uint64_t spread_bits(std::uint64_t v) {
  if constexpr (D == 1) return v;
  std::uint64_t r = 0;
  for (int b = 0; b < 21; ++b) r |= ((v >> b) & 1u) << (b * D);
  return r;
}
}  // namespace detail

// The Morton code of a point on the grid of cells of width `cell` over the domain box. Points
// outside the box are clamped to the edge cells (an escaping particle still sorts).
template <int D>
class MortonGrid {
 public:
  MortonGrid(const Domain<D>& dom, double cell) : lo_(dom.lo) {
    for (int d = 0; d < D; ++d) {
      const auto cells = std::clamp<double>(std::ceil(dom.length(d) / cell), 1.0, double(1 << 21));
      inv_[d] = cells / dom.length(d);
      top_[d] = static_cast<std::int64_t>(cells) - 1;
    }
  }
  // x[d][i]: the point's coordinates.
  std::uint64_t code(const std::array<const double*, D>& x, std::size_t i) const {
    std::uint64_t code = 0;
    for (int d = 0; d < D; ++d) {
      const auto c = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((x[d][i] - lo_[d]) * inv_[d])), 0, top_[d]);
      code |= detail::spread_bits<D>(static_cast<std::uint64_t>(c)) << d;
    }
    return code;
  }

 private:
  std::array<double, D> lo_;
  std::array<double, D> inv_;
  std::array<std::int64_t, D> top_;
};

// Indices begin..end-1 in Morton order of the cells of width `cell` that hold the particles, those
// in one cell by tie[i] (distinct keys; without `tie` by the index); returns them as a list of old
// indices (new position k holds the particle that was at order[k]).
template <int D>
std::vector<std::uint32_t> morton_order(const std::array<const double*, D>& x, std::size_t begin, std::size_t end,
                                        const Domain<D>& dom, double cell, const std::uint32_t* tie = nullptr) {
  const std::size_t n = end - begin;
  struct Key {
    std::uint64_t code;
    std::uint32_t tie, index;
    bool operator<(const Key& o) const { return code != o.code ? code < o.code : tie < o.tie; }
  };
  std::vector<Key> key(n);
  const MortonGrid<D> grid(dom, cell);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = begin + k;
    key[k] = {grid.code(x, i), tie ? tie[i] : static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i)};
  }
  std::sort(key.begin(), key.end());  // distinct (code, tie): deterministic
  std::vector<std::uint32_t> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = key[k].index;
  return order;
}

// v[begin + k] <- v[order[k]] for k < order.size(); `tmp` is scratch.
template <class T>
void permute_range(std::vector<T>& v, const std::vector<std::uint32_t>& order, std::size_t begin, std::vector<T>& tmp) {
  tmp.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) tmp[k] = v[order[k]];
  std::copy(tmp.begin(), tmp.end(), v.begin() + static_cast<std::ptrdiff_t>(begin));
}

}  // namespace sphmol
