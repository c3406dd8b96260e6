#pragma once
// The weakly compressible fluid row of the dam break and every continuity-density scene without a
// physical viscosity: continuity density (Niedoba 2012, eq 2.61), delta-SPH diffusion (optional),
// and the momentum equation with Monaghan's artificial viscosity inside the pressure bracket
// (Niedoba 2012, eq 2.71: dv_i/dt = -sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2 + Pi_ij) grad_i W_ij,
// pressure as Vukčević 2012, eq 117), in one sum over the row: each pair's neighbour data (v_j,
// rho_j, c_j, m_j) are loaded once, v_ij . x_ij is formed once, and p/rho^2 and m/rho are computed
// once per particle, not per pair, leaving one division per pair (in Pi_ij). The per-pair formulas
// are the separate terms' (continuity_rate, density_diffusion_pair, MonaghanPi); only the summation
// order differs from running them apart (round-off; tests/integration/test_fused_pair_passes.cpp).
// Chosen by the assembly when exactly these terms meet (discretization.combine_terms).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <omp.h>

#include "sphmol/physics/artificial_viscosity.hpp"
#include "sphmol/physics/density_diffusion.hpp"
#include "sphmol/physics/packed_neighbours.hpp"
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

template <int D, bool WithDiffusion>
class WeaklyCompressibleRow final : public PairTermFor<D, WeaklyCompressibleRow<D, WithDiffusion>> {
 public:
  // `viscosity` false: the scene has no artificial viscosity, and pi carries alpha = beta = 0 (Pi_ij = 0,
  // which costs the row nothing measurable against the separate terms' 1.9x).
  WeaklyCompressibleRow(double diffusion_coefficient, MonaghanPi pi, bool viscosity = true)
      : diff_(diffusion_coefficient), pi_(pi), viscosity_(viscosity) {}
  std::string_view name() const override {
    if (!viscosity_)
      return WithDiffusion ? "continuity_density+density_diffusion_molteni_colagrossi+pressure_gradient_117"
                           : "continuity_density+pressure_gradient_117";
    return WithDiffusion ? "continuity_density+density_diffusion_molteni_colagrossi+pressure_gradient_117+artificial_viscosity"
                         : "continuity_density+pressure_gradient_117+artificial_viscosity";
  }
  // Every contribution carries a factor F (Pi_ij's denominator is positive), so skin pairs add zeros.
  bool zero_beyond_support() const override { return true; }
  // Called by every thread of the pass's region (PairTerm::prepares_in_team); the barrier publishes
  // q, vol and the uniformity flags before any row reads them.
  bool prepares_in_team() const override { return true; }
  void prepare(Workspace<D>& w) const override {
#pragma omp single
    {
      pack_.resize(w.n);
      uniform_.assign(static_cast<std::size_t>(omp_get_num_threads()), kMassUniform | kSmoothingUniform);
    }
    const auto& m = w.particles->mass;
    const std::size_t nf = w.n_fluid;
    const double m0 = w.n > 0 ? m[0] : 0.0, h0 = w.n > 0 ? w.hs[0] : 0.0;
    bool same_m = true, same_h = true;
    PackedNeighbour<D>* const pk = pack_.data();
#pragma omp for schedule(static) nowait
    for (std::size_t i = 0; i < w.n; ++i) {
      PackedNeighbour<D>& p = pk[i];
      for (int d = 0; d < D; ++d) {
        p.x[d] = w.x[d][i];
        p.v[d] = w.v[d][i];
      }
      p.rho = w.rho[i];
      p.q = w.p[i] / (w.rho[i] * w.rho[i]);
      p.c = w.c[i];
      p.vol = WithDiffusion && i < nf ? m[i] / w.rho[i] : 0.0;  // delta-SPH: fluid neighbours only
      same_m = same_m && m[i] == m0;
      same_h = same_h && w.hs[i] == h0;
    }
    uniform_[static_cast<std::size_t>(omp_get_thread_num())] = (same_m ? kMassUniform : 0u) | (same_h ? kSmoothingUniform : 0u);
#pragma omp barrier
  }
  // The packed neighbour data of this evaluation, one per particle (after prepare()).
  const std::vector<PackedNeighbour<D>>& packed() const { return pack_; }
  // The row in blocks of pairs, each in three stages: (1) gather the neighbours' packed data into
  // contiguous arrays (physics/packed_neighbours.hpp), (2) every pair's arithmetic over those arrays with
  // no index and no branch, which vectorises (at x86-64-v3 one vdivpd serves four pairs' Pi_ij),
  // (3) the sums, in pair order. The arithmetic and the order of the additions are those of a single
  // loop over the pairs, so the result is the same bit for bit.
  // When every particle has the same mass (or the same h), the row reads m_i (h_i) for each pair
  // instead of gathering m_j (h_j): the same numbers, since (h + h)/2 = h exactly, with one gather
  // fewer per pair (the gathers are most of the row's memory traffic). The choice is made once per
  // row, not per pair.
  void row_impl(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    switch (uniform()) {
      case kMassUniform | kSmoothingUniform: return row<true, true>(w, i, r);
      case kMassUniform: return row<true, false>(w, i, r);
      case kSmoothingUniform: return row<false, true>(w, i, r);
      default: return row<false, false>(w, i, r);
    }
  }

  // Symmetric form (PairTerm::pair_record_size): with one mass for every particle, a pair's
  // continuity term m v_ij.x_ij F, its momentum term m (q_i + q_j + Pi_ij) F x_ij (the order of the
  // sums q_i + q_j, c_i + c_j, rho_i + rho_j does not matter, and v_ji.x_ji, r^2 and F are the same
  // numbers as v_ij.x_ij, r^2 and F) are the same for both directions up to the sign of x_ij, exactly;
  // the diffusion term 2 (rho_i - rho_j) F V_j is not symmetric and is recorded both ways.
  // Record of the pair i-j, i < j, written by row i: [diffusion j<-i, m v.x F, m (q_i + q_j + Pi) F x_ij
  // (D), diffusion i<-j] (without diffusion: [m v.x F, m (..) F x_ij (D)]). The order puts what row j
  // adds (its diffusion first) and what row i adds (its diffusion last) each in D + 2 consecutive
  // numbers, so in 2D each row adds one 256-bit load per pair into four running sums at once.
  std::size_t pair_record_size() const override { return kRecord; }
  bool pair_records_now() const override { return (uniform() & kMassUniform) != 0; }
  void pair_records(Workspace<D>& w, std::size_t i0, std::size_t i1, const std::uint32_t* off, const std::uint32_t* up,
                    const std::uint32_t* vj, const std::uint32_t* first, const KernelPass<D>& kernel,
                    double* out) const override {
    const bool same_h = (uniform() & kSmoothingUniform) != 0;
    if (kernel.geometry().periodic) {
      if (same_h) record_rows<true, true>(w, i0, i1, off, up, vj, first, kernel, out);
      else record_rows<false, true>(w, i0, i1, off, up, vj, first, kernel, out);
    } else {
      if (same_h) record_rows<true, false>(w, i0, i1, off, up, vj, first, kernel, out);
      else record_rows<false, false>(w, i0, i1, off, up, vj, first, kernel, out);
    }
  }
  void sum_pair_records(Workspace<D>& w, std::size_t i, const std::uint32_t* twin, std::uint32_t n_lower,
                        const double* upper, std::uint32_t n_upper, const double* all) const override {
#if defined(__AVX2__)
    if constexpr (D == 2 && WithDiffusion) {
      // The four sums of the scalar loops below in the lanes of one vector, each lane adding the same
      // numbers in the same order (a - r is a + (-r) exactly, and the sign flip is exact). Lower pairs
      // add [diffusion j<-i, cont, a_0, a_1] = record[0, 4); upper pairs [cont, a_0, a_1, diffusion]
      // = record[1, 5) with the momentum lanes negated; the lanes are rotated in between.
      __m256d s = _mm256_setzero_pd();
      for (std::uint32_t k = 0; k < n_lower; ++k) s = _mm256_add_pd(s, _mm256_loadu_pd(all + static_cast<std::size_t>(twin[k]) * kRecord));
      s = _mm256_permute4x64_pd(s, 0x39);  // (diff, cont, a0, a1) -> (cont, a0, a1, diff)
      const __m256d flip = _mm256_set_pd(0.0, -0.0, -0.0, 0.0);
      for (std::uint32_t k = 0; k < n_upper; ++k)
        s = _mm256_add_pd(s, _mm256_xor_pd(_mm256_loadu_pd(upper + static_cast<std::size_t>(k) * kRecord + 1), flip));
      alignas(32) double lane[4];
      _mm256_store_pd(lane, s);
      const double a[D] = {lane[1], lane[2]};
      return finish(w, i, lane[0], lane[3], a);
    }
#endif
    double cont = 0.0, diff = 0.0, a[D] = {};
    // Lower pairs, recorded by the other particle: x_ji = -x_ij, so a - (-m(..)F x_ij) = a + record.
    for (std::uint32_t k = 0; k < n_lower; ++k) {
      const double* rk = all + static_cast<std::size_t>(twin[k]) * kRecord;
      cont += rk[kCont];
      for (int d = 0; d < D; ++d) a[d] += rk[kMomentum + d];
      if constexpr (WithDiffusion) diff += rk[kDiffusionLower];
    }
    for (std::uint32_t k = 0; k < n_upper; ++k) {
      const double* rk = upper + static_cast<std::size_t>(k) * kRecord;
      cont += rk[kCont];
      for (int d = 0; d < D; ++d) a[d] -= rk[kMomentum + d];
      if constexpr (WithDiffusion) diff += rk[kDiffusionUpper];
    }
    finish(w, i, cont, diff, a);
  }

 private:
  static constexpr std::size_t kRecord = WithDiffusion ? 3 + D : 1 + D;
  // Where each number sits in a record (the layout above): the diffusion the larger index receives,
  // the continuity term, the momentum term, the diffusion the smaller index receives.
  static constexpr std::size_t kDiffusionLower = 0, kCont = WithDiffusion ? 1 : 0, kMomentum = kCont + 1,
                               kDiffusionUpper = kMomentum + D;
  static constexpr std::size_t kPrefetchAhead = 2048;  // bytes of records ahead of the row being written
  // Rows per call of records_in_registers: 2 to 8 ran alike, 1 and 32 (a whole chunk, whose
  // neighbour data has left the L1 cache by the second stage) slower (docs/performance.md).
  static constexpr std::size_t kRegisterRows = 4;

  unsigned uniform() const {
    unsigned u = kMassUniform | kSmoothingUniform;
    for (const unsigned f : uniform_) u &= f;
    return u;
  }

  static constexpr std::uint32_t kBlock = 64;  // pairs per block: the block's arrays stay in L1
  using Block = NeighbourBlock<D, kBlock>;

  // Stage (2), every pair's arithmetic for pairs [0, n) of row i, over contiguous arrays with no index
  // and no branch, which vectorises (at x86-64-v3 one vdivpd serves four pairs' Pi_ij): the neighbour
  // data in nb (stage (1), gather_neighbours), with mj (hj) the neighbours' masses (smoothing lengths)
  // unless SameMass (SameH), into pc (continuity), ps (momentum, before x_ij), pd (diffusion i<-j)
  // and, with Reverse, pr (diffusion j<-i).
  template <bool SameMass, bool SameH, bool Reverse>
  void arithmetic(const Workspace<D>& w, std::size_t i, const Block& nb, const double* mj, const double* hj,
                  const double* const (&dx)[D], const double* F, std::uint32_t n, double* pc, double* ps, double* pd,
                  double* pr) const {
    const PackedNeighbour<D>& pi = pack_[i];
    const double ri = pi.rho, qi = pi.q, hi = w.hs[i], ci = pi.c, mi = w.particles->mass[i];
    const double voli = WithDiffusion && Reverse ? pi.vol : 0.0;
    double vi[D];
    for (int d = 0; d < D; ++d) vi[d] = pi.v[d];
    // The viscosity's switch: min(vx, 0), or its smooth form (physics/artificial_viscosity.hpp), whose
    // polynomial step (core/polynomial_step.hpp) is arithmetic with no call, so the loop vectorises either way;
    // chosen once per block.
    const auto pairs = [&]<bool Smooth>() {
      for (std::uint32_t k = 0; k < n; ++k) {
        double vx = 0.0, r2 = 0.0;
        for (int d = 0; d < D; ++d) {
          vx += (vi[d] - nb.v[d][k]) * dx[d][k];
          r2 += dx[d][k] * dx[d][k];
        }
        double mk = mi, hij = hi;
        if constexpr (!SameMass) mk = mj[k];
        if constexpr (!SameH) hij = 0.5 * (hi + hj[k]);
        pc[k] = mk * vx * F[k];
        if constexpr (WithDiffusion) {
          pd[k] = density_diffusion_pair(ri, nb.rho[k], F[k], nb.vol[k]);
          if constexpr (Reverse) pr[k] = density_diffusion_pair(nb.rho[k], ri, F[k], voli);
        }
        const double cbar = 0.5 * (ci + nb.c[k]);
        const double sw = Smooth ? pi_.sw(vx, cbar, hij) : std::min(vx, 0.0);
        const double pij = pi_.switched(sw, r2, hij, cbar, 0.5 * (ri + nb.rho[k]));
        ps[k] = mk * (qi + nb.q[k] + pij) * F[k];
      }
    };
    if (pi_.width > 0.0) pairs.template operator()<true>();
    else pairs.template operator()<false>();
  }
  // The neighbours' values of a per-particle array for lanes [0, gathered_lanes(n)) (padded as
  // gather_neighbours).
  static void gather_values(const double* a, const std::uint32_t* j, std::uint32_t n, double* out) {
    for (std::uint32_t k = 0, lanes = gathered_lanes(n); k < lanes; ++k) out[k] = a[j[k < n ? k : n - 1]];
  }

  // The row in blocks of pairs (arithmetic() above), then (3) the sums, in pair order. The arithmetic and
  // the order of the additions are those of a single loop over the pairs, so the result is the same
  // bit for bit.
  // When every particle has the same mass (or the same h), the row reads m_i (h_i) for each pair
  // instead of gathering m_j (h_j): the same numbers, since (h + h)/2 = h exactly, with one gather
  // fewer per pair (the gathers are most of the row's memory traffic). The choice is made once per
  // row, not per pair.
  template <bool SameMass, bool SameH>
  void row(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    double cont = 0.0, diff = 0.0, a[D] = {};
    add_row<SameMass, SameH>(w, i, r, cont, diff, a);
    finish(w, i, cont, diff, a);
  }
  // Adds the pairs of r, in order, to the row's running sums.
  template <bool SameMass, bool SameH>
  void add_row(const Workspace<D>& w, std::size_t i, const PairRow<D>& r, double& cont, double& diff, double (&a)[D]) const {
    for (std::uint32_t k0 = 0; k0 < r.n; k0 += kBlock) {
      const std::uint32_t nb = std::min(kBlock, r.n - k0);
      Block blk;
      alignas(32) double mj[kBlock], hj[kBlock];
      gather_neighbours(pack_.data(), r.j + k0, nb, blk);
      if constexpr (!SameMass) gather_values(w.particles->mass.data(), r.j + k0, nb, mj);
      if constexpr (!SameH) gather_values(w.hs.data(), r.j + k0, nb, hj);
      const double* dx[D];
      for (int d = 0; d < D; ++d) dx[d] = r.dx[d] + k0;
      alignas(32) double pc[kBlock], pd[kBlock], ps[kBlock];
      arithmetic<SameMass, SameH, false>(w, i, blk, mj, hj, dx, r.F + k0, nb, pc, ps, pd, nullptr);
      for (std::uint32_t k = 0; k < nb; ++k) {
        cont += pc[k];
        if constexpr (WithDiffusion) diff += pd[k];
        for (int d = 0; d < D; ++d) a[d] -= ps[k] * r.dx[d][k0 + k];
      }
    }
  }

  template <bool SameH, bool Periodic>
  void record_rows(const Workspace<D>& w, std::size_t i0, std::size_t i1, const std::uint32_t* off, const std::uint32_t* up,
                   const std::uint32_t* vj, const std::uint32_t* first, const KernelPass<D>& kernel, double* out) const {
    const PairGeometry<D>& g = kernel.geometry();
#if defined(__AVX2__)
    if constexpr (D == 2 && WithDiffusion) {
      const auto rows = [&]<bool Smooth>() {
        for (std::size_t i = i0; i < i1; i += kRegisterRows)
          records_in_registers<SameH, Periodic, Smooth>(w, i, std::min(i1, i + kRegisterRows), off, up, vj, first, kernel, g, out);
      };
      if (pi_.width > 0.0) rows.template operator()<true>();
      else rows.template operator()<false>();
      return;
    }
#endif
    for (std::size_t i = i0; i < i1; ++i)
      records<SameH, Periodic>(w, i, vj + up[i], off[i + 1] - up[i], kernel, g, out + static_cast<std::size_t>(first[i]) * kRecord);
  }

  // Row i's upper pairs j[0 .. n) into records, in blocks: the neighbours' data (gather_neighbours),
  // their separations (Periodic: minimum image; the arithmetic of PairGeometry::separation) and F from
  // the kernel, then the arithmetic for both directions, then the stores. The loops run over whole
  // groups of four lanes (the padding lanes repeat the block's last pair and are not stored), so the
  // vectorised loops need no scalar remainder: a row has about ten upper pairs.
  template <bool SameH, bool Periodic>
  void records(const Workspace<D>& w, std::size_t i, const std::uint32_t* j, std::uint32_t n, const KernelPass<D>& kernel,
               const PairGeometry<D>& g, double* rec) const {
    // The records were last touched an evaluation ago and have left the cache, and the stores at the
    // end waited for their lines. Rows' records follow each other in memory, so ask for the lines of
    // the rows a few ahead now (a row writes about 10 lines): they arrive while this row computes.
    prefetch_records_ahead(rec, n);
    double xi[D];
    for (int d = 0; d < D; ++d) xi[d] = pack_[i].x[d];
    for (std::uint32_t k0 = 0; k0 < n; k0 += kBlock) {
      const std::uint32_t nb = std::min(kBlock, n - k0), lanes = gathered_lanes(nb);
      Block blk;
      alignas(32) double hj[kBlock];
      gather_neighbours(pack_.data(), j + k0, nb, blk);
      if constexpr (!SameH) gather_values(w.hs.data(), j + k0, nb, hj);
      alignas(32) double dx[D][kBlock], r2[kBlock], F[kBlock];
      for (std::uint32_t k = 0; k < lanes; ++k) {
        double s2 = 0.0;
        for (int d = 0; d < D; ++d) {
          double s = xi[d] - blk.x[d][k];
          if constexpr (Periodic) s -= g.period[d] * std::nearbyint(s * g.inv_period[d]);
          dx[d][k] = s;
          s2 += s * s;
        }
        r2[k] = s2;
      }
      kernel.gradient_factors(r2, F, lanes);
      const double* pdx[D];
      for (int d = 0; d < D; ++d) pdx[d] = dx[d];
      alignas(32) double pc[kBlock], pd[kBlock], pr[kBlock], ps[kBlock], sx[D][kBlock];
      arithmetic<true, SameH, true>(w, i, blk, nullptr, SameH ? nullptr : hj, pdx, F, lanes, pc, ps, pd, pr);
      for (int d = 0; d < D; ++d)
        for (std::uint32_t k = 0; k < lanes; ++k) sx[d][k] = ps[k] * dx[d][k];
      store_records(pc, sx, pd, pr, nb, rec + static_cast<std::size_t>(k0) * kRecord);
    }
  }

#if defined(__AVX2__)
  // records() for the rows [i0, i1) in 2D with diffusion (either switch): four pairs per vector,
  // each pair's neighbour data in registers from its load to its record, and the kernel pass called
  // once for the rows instead of once per row: (1) for every row, the first half of four packed
  // records (x, v) transposed, the separations, r^2 and v_ij . x_ij; (2) F for all of them; (3) for
  // every row, the second half (rho, q, c, vol) transposed, the arithmetic of arithmetic<true, SameH,
  // true>, and the records transposed into place. The operations are those of records(), in the same
  // order and without contraction (the build's -ffp-contract=off), so the records are the same
  // numbers bit for bit (tests/integration/test_symmetric_pairs.cpp: the full rows' state after 300
  // steps); what goes is the per-field arrays between the stages and most of a row's fixed cost (a
  // row has about fifteen upper pairs, skin included).
  template <bool SameH, bool Periodic, bool Smooth>
  void records_in_registers(const Workspace<D>& w, std::size_t i0, std::size_t i1, const std::uint32_t* off,
                            const std::uint32_t* up, const std::uint32_t* vj, const std::uint32_t* first,
                            const KernelPass<D>& kernel, const PairGeometry<D>& g, double* out) const {
    using V = __m256d;
    const V zero = _mm256_setzero_pd(), two = _mm256_set1_pd(2.0), half = _mm256_set1_pd(0.5);
    const V alpha = _mm256_set1_pd(pi_.alpha), beta = _mm256_set1_pd(pi_.beta), eta2 = _mm256_set1_pd(pi_.eta * pi_.eta);
    const V width = _mm256_set1_pd(pi_.width), offset = _mm256_set1_pd(pi_.offset), one = _mm256_set1_pd(1.0);
    [[maybe_unused]] V period[D], inv_period[D];
    if constexpr (Periodic)
      for (int d = 0; d < D; ++d) {
        period[d] = _mm256_set1_pd(g.period[d]);
        inv_period[d] = _mm256_set1_pd(g.inv_period[d]);
      }
    const double* base = &pack_[0].x[0];
    const double* hs = w.hs.data();
    constexpr std::size_t stride = sizeof(PackedNeighbour<D>) / sizeof(double);
    // The neighbours in lanes k .. k + 3 of a row with n upper pairs j; in its last, partial group the
    // padding lanes repeat the row's last pair (Tail) and are not stored.
    const auto lanes_of = []<bool Tail>(const std::uint32_t* j, std::uint32_t n, std::uint32_t k, std::uint32_t (&jl)[4]) {
      for (std::uint32_t l = 0; l < 4; ++l) jl[l] = j[Tail && k + l >= n ? n - 1 : k + l];
    };
    // Per thread, for the rows [i0, i1): dx_0, dx_1, r^2, v_ij . x_ij and F of every lane, each row's
    // lanes a multiple of four from the row's start.
    std::size_t lanes = 0;
    for (std::size_t i = i0; i < i1; ++i) lanes += gathered_lanes(off[i + 1] - up[i]);
    struct alignas(32) Group {
      double lane[4];
    };
    thread_local std::vector<Group> scratch;  // over-aligned type: aligned by operator new
    if (scratch.size() < 5 * (lanes / 4)) scratch.resize(5 * (lanes / 4));
    double* const sdx0 = scratch.data()->lane;
    double* const sdx1 = sdx0 + lanes;
    double* const sr2 = sdx1 + lanes;
    double* const svx = sr2 + lanes;
    double* const sF = svx + lanes;

    std::size_t at = 0;  // the row's first lane
    for (std::size_t i = i0; i < i1; ++i) {
      const std::uint32_t n = off[i + 1] - up[i], full = n & ~3u;
      const std::uint32_t* j = vj + up[i];
      const PackedNeighbour<D>& pi = pack_[i];
      const V xi0 = _mm256_set1_pd(pi.x[0]), xi1 = _mm256_set1_pd(pi.x[1]);
      const V vi0 = _mm256_set1_pd(pi.v[0]), vi1 = _mm256_set1_pd(pi.v[1]);
      const auto separations = [&]<bool Tail>(std::uint32_t k) {
        std::uint32_t jl[4];
        lanes_of.template operator()<Tail>(j, n, k, jl);
        V x0, x1, v0, v1;
        transpose4(_mm256_load_pd(base + jl[0] * stride), _mm256_load_pd(base + jl[1] * stride),
                  _mm256_load_pd(base + jl[2] * stride), _mm256_load_pd(base + jl[3] * stride), x0, x1, v0, v1);
        V s0 = xi0 - x0, s1 = xi1 - x1;
        if constexpr (Periodic) {
          constexpr int kNearest = _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC;  // nearbyint in the default mode
          s0 = s0 - period[0] * _mm256_round_pd(s0 * inv_period[0], kNearest);
          s1 = s1 - period[1] * _mm256_round_pd(s1 * inv_period[1], kNearest);
        }
        const std::size_t q = at + k;
        _mm256_store_pd(sdx0 + q, s0);
        _mm256_store_pd(sdx1 + q, s1);
        _mm256_store_pd(sr2 + q, (zero + s0 * s0) + s1 * s1);
        _mm256_store_pd(svx + q, (zero + (vi0 - v0) * s0) + (vi1 - v1) * s1);
      };
      std::uint32_t k = 0;
      for (; k < full; k += 4) separations.template operator()<false>(k);
      if (k < n) separations.template operator()<true>(k);
      at += gathered_lanes(n);
    }
    kernel.gradient_factors(sr2, sF, static_cast<std::uint32_t>(lanes));

    at = 0;
    for (std::size_t i = i0; i < i1; ++i) {
      const std::uint32_t n = off[i + 1] - up[i], full = n & ~3u;
      const std::uint32_t* j = vj + up[i];
      double* const rec = out + static_cast<std::size_t>(first[i]) * kRecord;
      prefetch_records_ahead(rec, n);  // as records()
      const PackedNeighbour<D>& pi = pack_[i];
      const V ri = _mm256_set1_pd(pi.rho), qi = _mm256_set1_pd(pi.q), ci = _mm256_set1_pd(pi.c), voli = _mm256_set1_pd(pi.vol);
      const V hi = _mm256_set1_pd(hs[i]), mi = _mm256_set1_pd(w.particles->mass[i]);
      [[maybe_unused]] const V width_hi = width * hi;  // the band's width h_ij (MonaghanPi::band) when every h is h_i
      const auto pairs = [&]<bool Tail>(std::uint32_t k) __attribute__((always_inline)) {  // inlined in both calls: the row's last group too
        std::uint32_t jl[4];
        lanes_of.template operator()<Tail>(j, n, k, jl);
        V rhoj, qj, cj, volj;
        transpose4(_mm256_load_pd(base + jl[0] * stride + 4), _mm256_load_pd(base + jl[1] * stride + 4),
                  _mm256_load_pd(base + jl[2] * stride + 4), _mm256_load_pd(base + jl[3] * stride + 4), rhoj, qj, cj, volj);
        const std::size_t q = at + k;
        const V s0 = _mm256_load_pd(sdx0 + q), s1 = _mm256_load_pd(sdx1 + q), rr = _mm256_load_pd(sr2 + q);
        const V vxk = _mm256_load_pd(svx + q), f = _mm256_load_pd(sF + q);
        V hij = hi;
        if constexpr (!SameH) hij = half * (hi + _mm256_set_pd(hs[jl[3]], hs[jl[2]], hs[jl[1]], hs[jl[0]]));
        const V pc = mi * vxk * f;
        const V pd = two * (ri - rhoj) * f * volj;  // density_diffusion_pair(ri, rho_j, F, vol_j)
        const V pr = two * (rhoj - ri) * f * voli;  // density_diffusion_pair(rho_j, ri, F, vol_i)
        // MonaghanPi::switched(sw, r2, hij, cbar, rhobar) with sw = min(vx, 0) (min_pd(0, vx) is
        // std::min(vx, 0.0), signed zeros and NaN included) or MonaghanPi::sw(vx, cbar, hij) =
        // vx P(t), t = offset - vx / delta. Outside the band (t <= 0 or t >= 1) P(t) is 0 or 1 exactly
        // and vx P(t) is min(vx, 0) bit for bit (signed zeros included), so a group with no pair in
        // the band takes min(vx, 0) and skips P's polynomial.
        const V cbar = half * (ci + cj), rhobar = half * (ri + rhoj);
        V sw = _mm256_min_pd(zero, vxk);
        if constexpr (Smooth) {
          const V t = offset - vxk / ((SameH ? width_hi : width * hij) * cbar);
          if (!_mm256_testz_pd(_mm256_cmp_pd(t, zero, _CMP_GT_OQ), _mm256_cmp_pd(t, one, _CMP_LT_OQ))) sw = vxk * switch_step_lanes(t);
        }
        const V t = hij * sw / ((rr + eta2 * hij * hij) * rhobar);
        const V pij = (beta * t * rhobar - alpha * cbar) * t;
        const V ps = mi * (qi + qj + pij) * f;
        V r[4];
        transpose4(pr, pc, ps * s0, ps * s1, r[0], r[1], r[2], r[3]);
        alignas(32) double last[4];
        _mm256_store_pd(last, pd);
        double* o = rec + static_cast<std::size_t>(k) * kRecord;
        // Only pairs below n: past them lie the next row's records.
        for (std::uint32_t l = 0; l < (Tail ? n - k : 4u); ++l) {
          _mm256_storeu_pd(o + l * kRecord, r[l]);
          o[l * kRecord + 4] = last[l];
        }
      };
      std::uint32_t k = 0;
      for (; k < full; k += 4) pairs.template operator()<false>(k);
      if (k < n) pairs.template operator()<true>(k);
      at += gathered_lanes(n);
    }
  }
#endif

  // Asks for the cache lines of the records a few rows after those of a row of n pairs at rec.
  static void prefetch_records_ahead(double* rec, std::uint32_t n) {
    const auto* ahead = reinterpret_cast<const char*>(rec) + kPrefetchAhead;
    for (std::size_t b = 0; b < static_cast<std::size_t>(n) * kRecord * sizeof(double); b += 64) __builtin_prefetch(ahead + b, 1, 3);
  }

  // Pairs [0, n)'s records (layout at pair_record_size) from the per-pair arrays. Only lanes below n
  // are stored: past them lie the next row's records.
  static void store_records(const double* pc, const double (&sx)[D][kBlock], const double* pd, const double* pr,
                            std::uint32_t n, double* rec) {
    std::uint32_t k = 0;
#if defined(__AVX__)
    if constexpr (D == 2 && WithDiffusion) {
      // Four pairs at a time: a 4x4 transpose of (pr, pc, sx_0, sx_1) gives each pair's first four
      // numbers, then its fifth.
      for (; k + 4 <= n; k += 4) {
        __m256d r[4];
        transpose4(_mm256_loadu_pd(pr + k), _mm256_loadu_pd(pc + k), _mm256_loadu_pd(sx[0] + k), _mm256_loadu_pd(sx[1] + k),
                   r[0], r[1], r[2], r[3]);
        double* out = rec + static_cast<std::size_t>(k) * kRecord;
        for (std::uint32_t l = 0; l < 4; ++l) {
          _mm256_storeu_pd(out + l * kRecord, r[l]);
          out[l * kRecord + 4] = pd[k + l];
        }
      }
    }
#endif
    for (; k < n; ++k) {
      double* out = rec + static_cast<std::size_t>(k) * kRecord;
      out[kCont] = pc[k];
      for (int d = 0; d < D; ++d) out[kMomentum + d] = sx[d][k];
      if constexpr (WithDiffusion) {
        out[kDiffusionUpper] = pd[k];
        out[kDiffusionLower] = pr[k];
      }
    }
  }

  void finish(Workspace<D>& w, std::size_t i, double cont, double diff, const double (&a)[D]) const {
    w.drhodt[i] += cont;
    if constexpr (WithDiffusion) w.drhodt[i] += diff_ * diff;
    for (int d = 0; d < D; ++d) w.dvdt[d][i] += a[d];
  }

  static constexpr unsigned kMassUniform = 1u, kSmoothingUniform = 2u;
  double diff_;  // delta h c0
  MonaghanPi pi_;
  bool viscosity_;
  // Per particle, this evaluation: the data a pair reads of its neighbour, p / rho^2 and (fluid) m / rho included.
  mutable std::vector<PackedNeighbour<D>> pack_;
  mutable std::vector<unsigned> uniform_;  // per thread of prepare(): its particles' uniformity flags
};

}  // namespace sphmol
