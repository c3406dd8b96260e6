#pragma once
// One particle's active pairs as a pair term reads them: neighbour j, dx = x_i - x_j (minimum image),
// W_ij, F_ij = (dW/dr)/r and the wall model's velocity factor, k = 0 .. n-1. The row is either a slice
// of the stored active-pair list (Workspace::pairs) or a per-thread buffer filled just before the
// row's terms run (rhs/fused_pair_pass.hpp); a term cannot tell the two apart.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "sphmol/rhs/workspace.hpp"

namespace sphmol {

template <int D>
struct PairRow {
  std::uint32_t n = 0;
  const std::uint32_t* j = nullptr;
  std::array<const double*, D> dx{};
  const double* W = nullptr;
  const double* F = nullptr;
  double* vfac = nullptr;  // writable: the wall model sets it before the viscous terms read it

  // The first wall pair of a fluid row: rows are sorted and walls follow the fluid, so a fluid row's
  // wall pairs form its tail [first_wall(n_fluid), n).
  std::uint32_t first_wall(std::size_t n_fluid) const {
    return static_cast<std::uint32_t>(std::lower_bound(j, j + n, static_cast<std::uint32_t>(n_fluid)) - j);
  }
};

// Row i of the stored active-pair list.
template <int D>
PairRow<D> stored_row(Workspace<D>& w, std::size_t i) {
  const std::uint32_t o = w.pairs.offset[i];
  PairRow<D> r;
  r.n = w.pairs.offset[i + 1] - o;
  r.j = w.pairs.j.data() + o;
  for (int d = 0; d < D; ++d) r.dx[d] = w.dx[d].data() + o;
  r.W = w.W.data() + o;
  r.F = w.F.data() + o;
  r.vfac = w.vfac.data() + o;
  return r;
}

// Per-thread storage for one row (fused passes): grows to the longest row seen, never shrinks.
template <int D>
struct RowBuffer {
  std::vector<std::uint32_t> j;
  std::array<std::vector<double>, D> dx;
  std::vector<double> W, F, vfac;
  std::vector<double> r2;  // scratch of the kernel pass: |dx|^2 of every Verlet pair of the row

  void reserve(std::size_t n) {
    if (j.size() >= n) return;
    j.resize(n);
    for (auto& c : dx) c.resize(n);
    W.resize(n);
    F.resize(n);
    vfac.resize(n);
    r2.resize(n);
  }
  PairRow<D> row(std::uint32_t n) {
    PairRow<D> r;
    r.n = n;
    r.j = j.data();
    for (int d = 0; d < D; ++d) r.dx[d] = dx[d].data();
    r.W = W.data();
    r.F = F.data();
    r.vfac = vfac.data();
    return r;
  }
};

}  // namespace sphmol
