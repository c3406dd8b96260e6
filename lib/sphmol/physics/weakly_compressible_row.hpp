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
#include <cstdint>
#include <vector>

#include <omp.h>

#include "sphmol/physics/artificial_viscosity.hpp"
#include "sphmol/physics/density_diffusion.hpp"
#include "sphmol/rhs/pair_term.hpp"

namespace sphmol {

template <int D, bool WithDiffusion>
class WeaklyCompressibleRow final : public PairTermFor<D, WeaklyCompressibleRow<D, WithDiffusion>> {
 public:
  WeaklyCompressibleRow(double diffusion_coefficient, MonaghanPi pi) : diff_(diffusion_coefficient), pi_(pi) {}
  std::string_view name() const override {
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
      q_.resize(w.n);
      if constexpr (WithDiffusion) vol_.resize(w.n);
      uniform_.assign(static_cast<std::size_t>(omp_get_num_threads()), kMassUniform | kSmoothingUniform);
    }
    const auto& m = w.particles->mass;
    const std::size_t nf = w.n_fluid;
    const double m0 = w.n > 0 ? m[0] : 0.0, h0 = w.n > 0 ? w.hs[0] : 0.0;
    bool same_m = true, same_h = true;
#pragma omp for schedule(static) nowait
    for (std::size_t i = 0; i < w.n; ++i) {
      q_[i] = w.p[i] / (w.rho[i] * w.rho[i]);
      if constexpr (WithDiffusion) vol_[i] = i < nf ? m[i] / w.rho[i] : 0.0;  // delta-SPH: fluid neighbours only
      same_m = same_m && m[i] == m0;
      same_h = same_h && w.hs[i] == h0;
    }
    uniform_[static_cast<std::size_t>(omp_get_thread_num())] = (same_m ? kMassUniform : 0u) | (same_h ? kSmoothingUniform : 0u);
#pragma omp barrier
  }
  // The row in blocks of pairs, each in three stages: (1) gather the neighbours' data into contiguous
  // arrays (indexed loads, which do not vectorise), (2) every pair's arithmetic over those arrays with
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
  // Record: [m v.x F, m (q_i + q_j + Pi) F x_ij (D), diffusion i<-j, diffusion j<-i].
  std::size_t pair_record_size() const override { return kRecord; }
  bool pair_records_now() const override { return (uniform() & kMassUniform) != 0; }
  void pair_records(Workspace<D>& w, std::size_t i, const std::uint32_t* j, std::uint32_t n, const KernelPass<D>& kernel,
                    double* rec) const override {
    const PairGeometry<D>& g = kernel.geometry();
    const bool same_h = (uniform() & kSmoothingUniform) != 0;
    if (g.periodic) same_h ? records<true, true>(w, i, j, n, kernel, rec) : records<false, true>(w, i, j, n, kernel, rec);
    else same_h ? records<true, false>(w, i, j, n, kernel, rec) : records<false, false>(w, i, j, n, kernel, rec);
  }
  void sum_pair_records(Workspace<D>& w, std::size_t i, const std::uint32_t* twin, std::uint32_t n_lower,
                        const double* upper, std::uint32_t n_upper, const double* all) const override {
    double cont = 0.0, diff = 0.0, a[D] = {};
    // Lower pairs, recorded by the other particle: x_ji = -x_ij, so a - (-m(..)F x_ij) = a + record.
    for (std::uint32_t k = 0; k < n_lower; ++k) {
      const double* rk = all + static_cast<std::size_t>(twin[k]) * kRecord;
      cont += rk[0];
      for (int d = 0; d < D; ++d) a[d] += rk[1 + d];
      if constexpr (WithDiffusion) diff += rk[2 + D];
    }
    for (std::uint32_t k = 0; k < n_upper; ++k) {
      const double* rk = upper + static_cast<std::size_t>(k) * kRecord;
      cont += rk[0];
      for (int d = 0; d < D; ++d) a[d] -= rk[1 + d];
      if constexpr (WithDiffusion) diff += rk[1 + D];
    }
    finish(w, i, cont, diff, a);
  }

 private:
  static constexpr std::size_t kRecord = WithDiffusion ? 3 + D : 1 + D;
  static constexpr std::size_t kPrefetchAhead = 2048;  // bytes of records ahead of the row being written

  unsigned uniform() const {
    unsigned u = kMassUniform | kSmoothingUniform;
    for (const unsigned f : uniform_) u &= f;
    return u;
  }

  // The per-pair numbers of pairs [k0, k0 + nb) of row i into pc (continuity), ps (momentum, before
  // x_ij), pd (diffusion i<-j) and, with Reverse, pr (diffusion j<-i): stage (1) gathers the
  // neighbours' data into contiguous arrays (indexed loads, which do not vectorise), stage (2) does
  // every pair's arithmetic over those arrays with no index and no branch, which vectorises (at
  // x86-64-v3 one vdivpd serves four pairs' Pi_ij).
  template <bool SameMass, bool SameH, bool Reverse>
  void block(const Workspace<D>& w, std::size_t i, const PairRow<D>& r, std::uint32_t k0, std::uint32_t nb, double* pc,
             double* ps, double* pd, double* pr) const {
    const double* m = w.particles->mass.data();
    const double* q = q_.data();
    const double* vol = vol_.data();
    const double ri = w.rho[i], qi = q[i], hi = w.hs[i], ci = w.c[i], mi = m[i];
    const double voli = WithDiffusion && Reverse ? vol[i] : 0.0;
    double vi[D];
    for (int d = 0; d < D; ++d) vi[d] = w.v[d][i];
    const std::uint32_t* jk = r.j + k0;
    const double* F = r.F + k0;
    const double* dx[D];
    for (int d = 0; d < D; ++d) dx[d] = r.dx[d] + k0;
    alignas(32) double mj[kBlock], rj[kBlock], qj[kBlock], hj[kBlock], cj[kBlock], volj[kBlock], vj[D][kBlock];
    for (std::uint32_t k = 0; k < nb; ++k) {
      const std::uint32_t j = jk[k];
      if constexpr (!SameMass) mj[k] = m[j];
      rj[k] = w.rho[j];
      qj[k] = q[j];
      if constexpr (!SameH) hj[k] = w.hs[j];
      cj[k] = w.c[j];
      if constexpr (WithDiffusion) volj[k] = vol[j];
      for (int d = 0; d < D; ++d) vj[d][k] = w.v[d][j];
    }
    for (std::uint32_t k = 0; k < nb; ++k) {
      double vx = 0.0, r2 = 0.0;
      for (int d = 0; d < D; ++d) {
        vx += (vi[d] - vj[d][k]) * dx[d][k];
        r2 += dx[d][k] * dx[d][k];
      }
      const double mk = SameMass ? mi : mj[k], hij = SameH ? hi : 0.5 * (hi + hj[k]);
      pc[k] = mk * vx * F[k];
      if constexpr (WithDiffusion) {
        pd[k] = density_diffusion_pair(ri, rj[k], F[k], volj[k]);
        if constexpr (Reverse) pr[k] = density_diffusion_pair(rj[k], ri, F[k], voli);
      }
      const double pij = pi_(vx, r2, hij, 0.5 * (ci + cj[k]), 0.5 * (ri + rj[k]));
      ps[k] = mk * (qi + qj[k] + pij) * F[k];
    }
  }

  // The row in blocks of pairs (block() above), then (3) the sums, in pair order. The arithmetic and
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
      alignas(32) double pc[kBlock], pd[kBlock], ps[kBlock];
      block<SameMass, SameH, false>(w, i, r, k0, nb, pc, ps, pd, nullptr);
      for (std::uint32_t k = 0; k < nb; ++k) {
        cont += pc[k];
        if constexpr (WithDiffusion) diff += pd[k];
        for (int d = 0; d < D; ++d) a[d] -= ps[k] * r.dx[d][k0 + k];
      }
    }
  }

  // Row i's upper pairs j[0 .. n) into records, in blocks: their separations (Periodic: minimum
  // image) and F from the kernel, then block()'s arithmetic for both directions, then the stores.
  template <bool SameH, bool Periodic>
  void records(const Workspace<D>& w, std::size_t i, const std::uint32_t* j, std::uint32_t n, const KernelPass<D>& kernel,
               double* rec) const {
    const PairGeometry<D>& g = kernel.geometry();
    // The records were last touched an evaluation ago and have left the cache, and the stores at the
    // end waited for their lines. Rows' records follow each other in memory, so ask for the lines of
    // the rows a few ahead now (a row writes about 10 lines): they arrive while this row computes.
    const auto* ahead = reinterpret_cast<const char*>(rec) + kPrefetchAhead;
    for (std::size_t b = 0; b < static_cast<std::size_t>(n) * kRecord * sizeof(double); b += 64) __builtin_prefetch(ahead + b, 1, 3);
    for (std::uint32_t k0 = 0; k0 < n; k0 += kBlock) {
      const std::uint32_t nb = std::min(kBlock, n - k0);
      alignas(32) double dx[D][kBlock], r2[kBlock], F[kBlock];
      for (std::uint32_t k = 0; k < nb; ++k) {
        double s[D];
        r2[k] = g.template separation<Periodic>(i, j[k0 + k], s);
        for (int d = 0; d < D; ++d) dx[d][k] = s[d];
      }
      kernel.gradient_factors(r2, F, nb);
      PairRow<D> r;
      r.n = nb;
      r.j = j + k0;
      for (int d = 0; d < D; ++d) r.dx[d] = dx[d];
      r.F = F;
      alignas(32) double pc[kBlock], pd[kBlock], pr[kBlock], ps[kBlock], sx[D][kBlock];
      block<true, SameH, true>(w, i, r, 0, nb, pc, ps, pd, pr);
      for (int d = 0; d < D; ++d)
        for (std::uint32_t k = 0; k < nb; ++k) sx[d][k] = ps[k] * dx[d][k];
      for (std::uint32_t k = 0; k < nb; ++k) {
        double* out = rec + static_cast<std::size_t>(k0 + k) * kRecord;
        out[0] = pc[k];
        for (int d = 0; d < D; ++d) out[1 + d] = sx[d][k];
        if constexpr (WithDiffusion) {
          out[1 + D] = pd[k];
          out[2 + D] = pr[k];
        }
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
  mutable std::vector<double> q_, vol_;  // p / rho^2 and (fluid) m / rho per particle, this evaluation
  mutable std::vector<unsigned> uniform_;  // per thread of prepare(): its particles' uniformity flags
  static constexpr std::uint32_t kBlock = 64;  // pairs per block: the block's arrays stay in L1
};

}  // namespace sphmol
