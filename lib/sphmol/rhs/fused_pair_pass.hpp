#pragma once
// A fused pair pass: for each row, the kernel pass fills a per-thread buffer with the row's active
// pairs (dx, W, F) straight from the Verlet list, and every pair term of the pass sums over that
// buffer in turn, while the neighbours' data are still in cache. Nothing per pair outlives the row, so
// the active-pair list (about 44 bytes per pair in 2D) is never stored: memory and memory traffic
// drop, and the kernel is still evaluated once per pair per pass. Terms whose output a later term
// reads at neighbouring particles end a pass (rhs/pair_pass_plan.hpp). Results equal those of the
// stored list bit for bit: the same pairs, in the same order, with the same arithmetic. Where every
// term of the pass adds nothing for a pair beyond the support, the rows also keep the Verlet list's
// skin pairs (W = F = 0) and the kernel pass skips compacting them away; the sums are unchanged.
#include <algorithm>
#include <memory>
#include <omp.h>
#include <string>
#include <vector>

#include "sphmol/rhs/kernel_pass.hpp"
#include "sphmol/rhs/pair_term.hpp"
#include "sphmol/rhs/row_schedule.hpp"

namespace sphmol {

template <int D>
class FusedPairPass final : public Term<D> {
 public:
  FusedPairPass(KernelPass<D>* kernel, std::vector<std::unique_ptr<PairTerm<D>>> terms)
      : kernel_(kernel), terms_(std::move(terms)) {
    for (const auto& t : terms_) {
      if (t->rows() != PairRows::dynamic_walls) fluid_.push_back(t.get());
      if (t->rows() != PairRows::fluid) walls_.push_back(t.get());
      if (!name_.empty()) name_ += '+';
      name_ += t->name();
      compact_fluid_ = compact_fluid_ || (t->rows() != PairRows::dynamic_walls && !t->zero_beyond_support());
      compact_walls_ = compact_walls_ || (t->rows() != PairRows::fluid && !t->zero_beyond_support());
    }
  }
  // Whether fluid rows / wall rows are compacted to the active pairs (false: every term of those rows
  // takes the skin pairs, PairTerm::zero_beyond_support).
  bool compacts_fluid_rows() const { return compact_fluid_; }
  bool compacts_wall_rows() const { return compact_walls_; }
  std::string_view name() const override { return name_; }
  const std::vector<std::unique_ptr<PairTerm<D>>>& terms() const { return terms_; }

  // Called by every thread of the system's region (Term::runs_in_team): the set-up in `single`, the
  // terms' own preparations, the rows, and a barrier at the end, after which every row is written.
  bool runs_in_team() const override { return true; }
  void apply(Workspace<D>& w) const override {
    const PairList& verlet = *w.verlet;
    const std::size_t nf = w.n_fluid;
#pragma omp single
    {
      kernel_->prepare(w);
      for (const auto& t : terms_)
        if (!t->prepares_in_team()) t->prepare(w);
      std::size_t wall_hi = nf;  // wall rows run up to the furthest any term needs
      for (const auto* t : walls_) wall_hi = std::max(wall_hi, row_range(t->rows(), w).second);
      const int threads = omp_get_num_threads();
      const auto T = static_cast<std::size_t>(threads);
      buffers_.resize(T);
      if (w.pair_thread_seconds.size() < T) w.pair_thread_seconds.resize(T, 0.0);
      // Rows shared by cost in contiguous ranges, with helping at the end (rhs/row_schedule.hpp).
      schedule_.reset(threads, 2);
      schedule_.place(0, verlet.offset.data(), 0, nf);
      schedule_.place(1, verlet.offset.data(), nf, wall_hi);
    }  // the barrier of `single`: every thread sees the schedule
    for (const auto& t : terms_)
      if (t->prepares_in_team()) t->prepare(w);  // each ends with a barrier
    {
      const int thread = omp_get_thread_num();
      const double start = omp_get_wtime();
      RowBuffer<D>& buf = buffers_[static_cast<std::size_t>(thread)];
      // No barrier between fluid rows (set 0) and wall rows (set 1): a row's terms read no other
      // row's output (one pass).
      schedule_.run(thread, [&](int set, std::size_t i0, std::size_t i1) {
        if (set == 0) {
          for (std::size_t i = i0; i < i1; ++i) {
            const PairRow<D> row = buf.row(kernel_->fill_row(verlet, i, buf, compact_fluid_));
            for (const auto* t : fluid_) t->row(w, i, row);
          }
        } else {
          for (std::size_t i = i0; i < i1; ++i) {
            const PairRow<D> row = buf.row(kernel_->fill_row(verlet, i, buf, compact_walls_));
            for (const auto* t : walls_)
              if (i < row_range(t->rows(), w).second) t->row(w, i, row);
          }
        }
      });
      w.pair_thread_seconds[static_cast<std::size_t>(thread)] += omp_get_wtime() - start;
    }
#pragma omp barrier
  }

 private:
  KernelPass<D>* kernel_;  // owned by the system, which owns this pass too
  std::vector<std::unique_ptr<PairTerm<D>>> terms_;
  std::vector<const PairTerm<D>*> fluid_, walls_;  // the terms with fluid rows, with wall rows
  std::string name_;
  bool compact_fluid_ = false, compact_walls_ = false;
  mutable std::vector<RowBuffer<D>> buffers_;  // one per thread, kept between evaluations
  mutable RowSchedule schedule_;
};

}  // namespace sphmol
