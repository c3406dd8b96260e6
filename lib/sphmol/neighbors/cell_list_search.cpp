#include "sphmol/neighbors/cell_list_search.hpp"

#include <algorithm>
#include <cmath>
#include <omp.h>

namespace sphmol {

template <int D>
void CellListSearch<D>::build(const SearchInput<D>& in, PairList& out) {
  const Domain<D>& dom = *in.domain;
  dom.require_pair_radius(in.radius);
  std::array<int, D> ncell;
  std::array<double, D> inv_size;
  std::size_t total = 1;
  for (int d = 0; d < D; ++d) {
    ncell[d] = std::max(1, static_cast<int>(std::floor(dom.length(d) / in.radius)));
    // Keep the cell count bounded for very small radii in a large box.
    ncell[d] = std::min(ncell[d], 1 << 20);
    inv_size[d] = ncell[d] / dom.length(d);
    total *= static_cast<std::size_t>(ncell[d]);
  }
  auto cell_coord = [&](std::size_t i, int d) {
    const int c = static_cast<int>(std::floor((in.x[d][i] - dom.lo[d]) * inv_size[d]));
    return std::clamp(c, 0, ncell[d] - 1);
  };
  // Counting sort of particles by cell.
  cell_of_.resize(in.n);
  cell_start_.assign(total + 1, 0);
  for (std::size_t i = 0; i < in.n; ++i) {
    std::size_t c = 0;
    for (int d = D - 1; d >= 0; --d) c = c * ncell[d] + cell_coord(i, d);
    cell_of_[i] = static_cast<std::uint32_t>(c);
    ++cell_start_[c + 1];
  }
  for (std::size_t c = 0; c < total; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_items_.resize(in.n);
  {
    std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t i = 0; i < in.n; ++i) cell_items_[fill[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
  }

  int combos = 1;
  for (int d = 0; d < D; ++d) combos *= 3;
  out.clear(in.n);
  // Rows in parallel: each thread fills a contiguous block of rows into its own buffer, and the
  // buffers are joined in block order, so the list is the same for any thread count.
  const long n = static_cast<long>(in.n);
  std::vector<std::size_t> block_start;
#pragma omp parallel
  {
    const int threads = omp_get_num_threads(), t = omp_get_thread_num();
    const long lo = n * t / threads, hi = n * (t + 1) / threads;
    std::vector<std::uint32_t> local, row;
    std::vector<std::size_t> cells;
    for (long i = lo; i < hi; ++i) {
      row.clear();
      cells.clear();
      for (int k = 0; k < combos; ++k) {
        std::size_t c = 0;
        bool ok = true;
        for (int d = D - 1, kk = k; d >= 0; --d) {
          int off = 0;
          {  // digit d of k in base 3
            int t3 = kk;
            for (int e = 0; e < d; ++e) t3 /= 3;
            off = t3 % 3 - 1;
          }
          int cd = cell_coord(static_cast<std::size_t>(i), d) + off;
          if (cd < 0 || cd >= ncell[d]) {
            if (!dom.periodic[d]) { ok = false; break; }
            cd = (cd + ncell[d]) % ncell[d];
          }
          c = c * ncell[d] + cd;
        }
        if (ok) cells.push_back(c);
      }
      // With fewer than three cells in a periodic direction the same cell appears twice.
      std::sort(cells.begin(), cells.end());
      cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
      for (const std::size_t c : cells)
        for (std::uint32_t q = cell_start_[c]; q < cell_start_[c + 1]; ++q)
          if (detail::is_pair(in, static_cast<std::size_t>(i), cell_items_[q])) row.push_back(cell_items_[q]);
      std::sort(row.begin(), row.end());
      local.insert(local.end(), row.begin(), row.end());
      out.offset[i + 1] = static_cast<std::uint32_t>(local.size());  // within the block, fixed below
    }
#pragma omp single
    block_start.assign(static_cast<std::size_t>(threads) + 1, 0);
    block_start[t + 1] = local.size();
#pragma omp barrier
#pragma omp single
    {
      for (int b = 0; b < threads; ++b) block_start[b + 1] += block_start[b];
      out.j.resize(block_start[threads]);
    }
    const auto base = static_cast<std::uint32_t>(block_start[t]);
    for (long i = lo; i < hi; ++i) out.offset[i + 1] += base;
    std::copy(local.begin(), local.end(), out.j.begin() + static_cast<std::ptrdiff_t>(base));
  }
}

template class CellListSearch<1>;
template class CellListSearch<2>;
template class CellListSearch<3>;

}  // namespace sphmol
