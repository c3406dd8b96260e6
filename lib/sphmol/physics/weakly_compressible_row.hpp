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
    unsigned u = kMassUniform | kSmoothingUniform;
    for (const unsigned f : uniform_) u &= f;
    switch (u) {
      case kMassUniform | kSmoothingUniform: return row<true, true>(w, i, r);
      case kMassUniform: return row<true, false>(w, i, r);
      case kSmoothingUniform: return row<false, true>(w, i, r);
      default: return row<false, false>(w, i, r);
    }
  }

 private:
  template <bool SameMass, bool SameH>
  void row(Workspace<D>& w, std::size_t i, const PairRow<D>& r) const {
    const double* m = w.particles->mass.data();
    const double* q = q_.data();
    const double* vol = vol_.data();
    const double ri = w.rho[i], qi = q[i], hi = w.hs[i], ci = w.c[i], mi = m[i];
    double vi[D];
    for (int d = 0; d < D; ++d) vi[d] = w.v[d][i];
    double cont = 0.0, diff = 0.0, a[D] = {};
    for (std::uint32_t k0 = 0; k0 < r.n; k0 += kBlock) {
      const std::uint32_t nb = std::min(kBlock, r.n - k0);
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
      alignas(32) double pc[kBlock], pd[kBlock], ps[kBlock];
      for (std::uint32_t k = 0; k < nb; ++k) {
        double vx = 0.0, r2 = 0.0;
        for (int d = 0; d < D; ++d) {
          vx += (vi[d] - vj[d][k]) * dx[d][k];
          r2 += dx[d][k] * dx[d][k];
        }
        const double mk = SameMass ? mi : mj[k], hij = SameH ? hi : 0.5 * (hi + hj[k]);
        pc[k] = mk * vx * F[k];
        if constexpr (WithDiffusion) pd[k] = density_diffusion_pair(ri, rj[k], F[k], volj[k]);
        const double pij = pi_(vx, r2, hij, 0.5 * (ci + cj[k]), 0.5 * (ri + rj[k]));
        ps[k] = mk * (qi + qj[k] + pij) * F[k];
      }
      for (std::uint32_t k = 0; k < nb; ++k) {
        cont += pc[k];
        if constexpr (WithDiffusion) diff += pd[k];
        for (int d = 0; d < D; ++d) a[d] -= ps[k] * dx[d][k];
      }
    }
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
