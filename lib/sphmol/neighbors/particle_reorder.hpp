#pragma once
// Particle order for memory locality: particles sorted along a Morton (Z-order) curve through a grid
// of cells, so that particles close in space are close in memory and the pair loops of the RHS read
// neighbour data from cache instead of from all over the arrays. SphSystem applies the order to its
// workspace index only (the ODE state keeps its order; rhs/sph_system.cpp), each time the Verlet list
// is rebuilt. Within a cell particles keep their previous relative order, so the order is a pure
// function of the positions and the previous order (never of the thread count).
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

// Indices begin..end-1 in Morton order of the cells of width `cell` that hold the particles; returns
// them as a list of old indices (new position k holds the particle that was at order[k]).
// Positions outside the domain box are clamped to the edge cells (an escaping particle still sorts).
template <int D>
std::vector<std::uint32_t> morton_order(const std::array<const double*, D>& x, std::size_t begin, std::size_t end,
                                        const Domain<D>& dom, double cell) {
  const std::size_t n = end - begin;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> key(n);
  std::array<double, D> inv;
  std::array<std::int64_t, D> top;
  for (int d = 0; d < D; ++d) {
    const auto cells = std::clamp<double>(std::ceil(dom.length(d) / cell), 1.0, double(1 << 21));
    inv[d] = cells / dom.length(d);
    top[d] = static_cast<std::int64_t>(cells) - 1;
  }
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = begin + k;
    std::uint64_t code = 0;
    for (int d = 0; d < D; ++d) {
      const auto c = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((x[d][i] - dom.lo[d]) * inv[d])), 0, top[d]);
      code |= detail::spread_bits<D>(static_cast<std::uint64_t>(c)) << d;
    }
    key[k] = {code, static_cast<std::uint32_t>(i)};
  }
  std::sort(key.begin(), key.end());  // ties broken by the old index: deterministic
  std::vector<std::uint32_t> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = key[k].second;
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
