#include "sphmol/neighbors/cell_list_search.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
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
  const long n = static_cast<long>(in.n);
  cell_of_.resize(in.n);
  cell_start_.resize(total + 1);
  cell_items_.resize(in.n);
  // Counting sort by cell, in parallel and stable: thread t counts its static range of particles per
  // cell, a cell's particles are placed thread by thread (each range ascending), so every cell lists
  // its particles in ascending order, as a serial sort would, for any thread count.
#pragma omp parallel
  {
    const int threads = omp_get_num_threads(), t = omp_get_thread_num();
#pragma omp single
    count_.resize(static_cast<std::size_t>(threads));
    std::vector<std::uint32_t>& count = count_[static_cast<std::size_t>(t)];
    count.assign(total, 0);
    const long lo = n * t / threads, hi = n * (t + 1) / threads;
    // Each particle's cell (index with direction 0 fastest).
    for (long i = lo; i < hi; ++i) {
      std::size_t c = 0;
      for (int d = D - 1; d >= 0; --d) {
        const int cd = static_cast<int>(std::floor((in.x[d][i] - dom.lo[d]) * inv_size[d]));
        c = c * ncell[d] + std::clamp(cd, 0, ncell[d] - 1);
      }
      cell_of_[i] = static_cast<std::uint32_t>(c);
      ++count[c];
    }
#pragma omp barrier
    // Per cell range: the cells' totals, then (after the ranges' sums are known) each thread's start
    // in each cell, written over its count.
    const std::size_t c_lo = total * static_cast<std::size_t>(t) / static_cast<std::size_t>(threads);
    const std::size_t c_hi = total * static_cast<std::size_t>(t + 1) / static_cast<std::size_t>(threads);
    std::uint32_t range_sum = 0;
    for (std::size_t c = c_lo; c < c_hi; ++c)
      for (int u = 0; u < threads; ++u) range_sum += count_[static_cast<std::size_t>(u)][c];
#pragma omp single
    range_start_.assign(static_cast<std::size_t>(threads) + 1, 0);
    range_start_[static_cast<std::size_t>(t) + 1] = range_sum;
#pragma omp barrier
    std::uint32_t at = 0;
    for (int u = 0; u < t; ++u) at += range_start_[static_cast<std::size_t>(u) + 1];
    for (std::size_t c = c_lo; c < c_hi; ++c) {
      cell_start_[c] = at;
      for (int u = 0; u < threads; ++u) {
        std::uint32_t& k = count_[static_cast<std::size_t>(u)][c];
        const std::uint32_t items = k;
        k = at;
        at += items;
      }
    }
    if (t + 1 == threads) cell_start_[total] = at;
#pragma omp barrier
    for (long i = lo; i < hi; ++i) cell_items_[count[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
  }

  // Rows cell by cell: the 3^D neighbour cells and their particles, merged into one ascending
  // candidate list, are found once per cell and shared by all its particles, so each row comes out
  // sorted. Each thread takes a contiguous run of cells holding about n / threads particles and
  // writes rows into its own buffer; row lengths then give the offsets, and each thread copies its
  // rows to their place. A row depends only on the particle, never on the split: the list is the
  // same for any thread count.
  int combos = 1;
  for (int d = 0; d < D; ++d) combos *= 3;
  out.offset.assign(in.n + 1, 0);
  row_at_.resize(in.n);
  std::vector<std::size_t> block_sum;
#pragma omp parallel
  {
    const int threads = omp_get_num_threads(), t = omp_get_thread_num();
#pragma omp single
    {
      block_sum.assign(static_cast<std::size_t>(threads) + 1, 0);
    }
    // The thread's rows, back to back in local[0, used). Sized from the previous list (its share plus
    // 10 %), grown by a quarter when short: doubling made this buffer up to twice the list at the peak.
    // Not zero-filled (make_unique_for_overwrite): every entry read back was written.
    std::size_t capacity = out.j.size() / static_cast<std::size_t>(threads) * 11 / 10;
    auto local = std::make_unique_for_overwrite<std::uint32_t[]>(capacity);
    std::size_t used = 0;
    const auto cell_at_or_after = [&](long particles) {
      const auto end = cell_start_.begin() + static_cast<std::ptrdiff_t>(total);
      return static_cast<std::size_t>(
          std::lower_bound(cell_start_.begin(), end, static_cast<std::uint32_t>(particles)) - cell_start_.begin());
    };
    const std::size_t c_lo = cell_at_or_after(n * t / threads);
    const std::size_t c_hi = t + 1 == threads ? total : cell_at_or_after(n * (t + 1) / threads);
    const detail::PairDistance<D> pd(in);
    std::vector<std::size_t> cells;
    std::vector<std::uint32_t> cand;            // candidate neighbours of the cell, ascending
    std::array<std::vector<double>, D> cand_x;  // their coordinates, contiguous
    // 1: a fluid particle; 1: not taken out (Kind::Out, which forms no pair); 1: listed in the row at hand
    std::vector<std::uint8_t> cand_fluid, cand_in, cand_on;
    for (std::size_t c = c_lo; c < c_hi; ++c) {
      if (cell_start_[c] == cell_start_[c + 1]) continue;
      std::array<int, D> cc;
      std::size_t rest = c;
      for (int d = 0; d < D; ++d) {
        cc[d] = static_cast<int>(rest % static_cast<std::size_t>(ncell[d]));
        rest /= static_cast<std::size_t>(ncell[d]);
      }
      cells.clear();
      for (int k = 0; k < combos; ++k) {
        std::size_t nc = 0;
        bool ok = true;
        // Offset in direction d: digit d of k in base 3, minus one.
        int pow3 = combos;
        for (int d = D - 1; d >= 0; --d) {
          pow3 /= 3;
          int cd = cc[d] + (k / pow3) % 3 - 1;
          if (cd < 0 || cd >= ncell[d]) {
            if (!dom.periodic[d]) {
              ok = false;
              break;
            }
            cd = (cd + ncell[d]) % ncell[d];
          }
          nc = nc * ncell[d] + cd;
        }
        if (ok) cells.push_back(nc);
      }
      // With fewer than three cells in a periodic direction the same cell appears twice.
      std::sort(cells.begin(), cells.end());
      cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
      cand.clear();
      for (const std::size_t nc : cells)
        cand.insert(cand.end(), cell_items_.begin() + cell_start_[nc], cell_items_.begin() + cell_start_[nc + 1]);
      std::sort(cand.begin(), cand.end());
      const std::size_t m = cand.size();
      for (int d = 0; d < D; ++d) {
        cand_x[d].resize(m);
        for (std::size_t k = 0; k < m; ++k) cand_x[d][k] = in.x[d][cand[k]];
      }
      cand_fluid.resize(m);
      cand_in.resize(m);
      cand_on.resize(m);
      for (std::size_t k = 0; k < m; ++k) {
        cand_fluid[k] = in.kind[cand[k]] == Kind::Fluid ? 1 : 0;
        cand_in[k] = in.kind[cand[k]] != Kind::Out ? 1 : 0;
      }
      for (std::uint32_t q = cell_start_[c]; q < cell_start_[c + 1]; ++q) {
        const std::uint32_t i = cell_items_[q];
        const bool fluid_i = in.kind[i] == Kind::Fluid;
        const std::uint8_t in_i = in.kind[i] != Kind::Out ? 1 : 0;
        std::array<double, D> xi;
        for (int d = 0; d < D; ++d) xi[d] = in.x[d][i];
        // pd.is_pair(in, i, cand[k]) on the copied coordinates, in two loops: the tests into a mask
        // over contiguous arrays, with no store that depends on the outcome, which vectorises; then
        // the listed candidates moved to the row (the one serial dependency, len).
        const std::uint8_t fi = fluid_i ? 1 : 0;
        std::uint8_t* const on = cand_on.data();
        for (std::size_t k = 0; k < m; ++k) {
          std::array<double, D> dx;
          for (int d = 0; d < D; ++d) dx[d] = xi[d] - cand_x[d][k];
          on[k] = static_cast<std::uint8_t>(pd.within(dx) & (cand[k] != i) & (fi | cand_fluid[k]) & in_i & cand_in[k]);
        }
        if (counting_) {
          std::uint32_t len = 0;
          for (std::size_t k = 0; k < m; ++k) len += on[k];
          out.offset[i + 1] = len;
          continue;
        }
        // A row holds at most m entries (room for them per row, not per cell: one crowded cell
        // could otherwise ask for m^2).
        if (capacity < used + m) {
          capacity = std::max(capacity + capacity / 4, used + m);
          auto grown = std::make_unique_for_overwrite<std::uint32_t[]>(capacity);
          std::copy(local.get(), local.get() + used, grown.get());
          local = std::move(grown);
        }
        std::uint32_t* const row = local.get() + used;
        std::size_t len = 0;
        for (std::size_t k = 0; k < m; ++k) {
          row[len] = cand[k];
          len += on[k];
        }
        row_at_[i] = static_cast<std::uint32_t>(used);
        out.offset[i + 1] = static_cast<std::uint32_t>(len);  // length; offsets below
        used += len;
      }
    }
    // Row lengths to offsets: a prefix sum over fixed blocks of rows, then the block sums.
    const long lo = n * t / threads, hi = n * (t + 1) / threads;
#pragma omp barrier
    if (!counting_) {  // the same on every thread (barriers inside)
      std::size_t sum = 0;
      for (long i = lo; i < hi; ++i) sum += out.offset[i + 1];
      block_sum[t + 1] = sum;
#pragma omp barrier
#pragma omp single
      {
        for (int b = 0; b < threads; ++b) block_sum[b + 1] += block_sum[b];
        out.j.resize(block_sum[threads]);
      }
      auto running = static_cast<std::uint32_t>(block_sum[t]);
      for (long i = lo; i < hi; ++i) out.offset[i + 1] = running += out.offset[i + 1];
#pragma omp barrier
      for (std::size_t c = c_lo; c < c_hi; ++c)
        for (std::uint32_t q = cell_start_[c]; q < cell_start_[c + 1]; ++q) {
          const std::uint32_t i = cell_items_[q];
          const std::uint32_t* const from = local.get() + row_at_[i];
          std::copy(from, from + (out.offset[i + 1] - out.offset[i]), out.j.begin() + out.offset[i]);
        }
    }
    // Released, not kept for the next build: with it the list existed twice between builds, which
    // made a quarter of the peak memory at 1e6 particles (sph-bench Memory).
    local.reset();
  }
}

template <int D>
std::vector<std::uint32_t> CellListSearch<D>::row_lengths(const SearchInput<D>& in) {
  PairList lengths;  // offset[i + 1]: row i's length; no pair stored
  counting_ = true;
  try {
    build(in, lengths);
  } catch (...) {
    counting_ = false;
    throw;
  }
  counting_ = false;
  return std::vector<std::uint32_t>(lengths.offset.begin() + 1, lengths.offset.end());
}

template class CellListSearch<1>;
template class CellListSearch<2>;
template class CellListSearch<3>;

}  // namespace sphmol
