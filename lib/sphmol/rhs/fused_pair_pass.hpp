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
// Symmetric evaluation: when the fluid rows have one term with a symmetric form
// (PairTerm::pair_record_size; the weakly compressible row), every fluid pair is evaluated once,
// kernel included, in the row of its smaller index, into a record that both rows then sum in their
// own order (neighbors/pair_twins.hpp): half the kernel evaluations and half the pair arithmetic,
// for one more barrier and the records' memory traffic. The sums are the same numbers added in the
// same order, so results equal the full rows' bit for bit, for any thread count.
#include <algorithm>
#include <cassert>
#include <atomic>
#include <memory>
#include <omp.h>
#include <string>
#include <vector>

#include "sphmol/neighbors/pair_twins.hpp"
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
    symmetric_form_ = fluid_.size() == 1 && fluid_[0]->rows() == PairRows::fluid && fluid_[0]->pair_record_size() > 0 &&
                      !compact_fluid_;
  }
  // Whether the pass may evaluate fluid pairs once (above). On by default in 1D and 2D, off in 3D:
  // there a row's lower neighbours lie up to a plane of particles back, their records (about 2 KiB
  // per row) have left the L2 cache when the row reads them, and the 3D dam break example ran 1.2x
  // slower symmetric (docs/performance.md). Off: every row in full; the results are the same.
  bool has_symmetric_form() const { return symmetric_form_; }
  void set_symmetric(bool on) { symmetric_ = on; }
  // Evaluations that ran symmetrically (each also needs one mass for all particles and a symmetric
  // Verlet list at that evaluation).
  long symmetric_evaluations() const { return symmetric_evaluations_; }
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
      deferred_.resize(T);
      if (deferred_next_size_ < T) {
        deferred_next_ = std::make_unique<PaddedCursor[]>(T);
        deferred_next_size_ = T;
      }
      for (std::size_t t = 0; t < T; ++t) deferred_next_[t].value.store(0, std::memory_order_relaxed);
      if (w.pair_thread_seconds.size() < T) w.pair_thread_seconds.resize(T, 0.0);
      // Rows shared by cost in contiguous ranges, with helping at the end (rhs/row_schedule.hpp).
      schedule_.reset(threads, 2);
      schedule_.place(0, verlet.offset.data(), 0, nf);
      schedule_.place(1, verlet.offset.data(), nf, wall_hi);
      if (symmetric_form_ && symmetric_) {
        ++epoch_;
        twins_stale_ = twins_list_ != &verlet || twins_rebuilds_ != w.verlet_rebuilds ||
                       twins_entries_ != verlet.pairs() || twins_.rows() != nf;
      }
    }  // the barrier of `single`: every thread sees the schedule
    for (const auto& t : terms_)
      if (t->prepares_in_team()) t->prepare(w);  // each ends with a barrier
    // Every thread takes the same branch: what it reads was written before a barrier.
    if (symmetric_form_ && symmetric_ && kernel_->uniform_h() && fluid_[0]->pair_records_now()) {
      if (twins_stale_) make_twins(w);
      if (twins_.complete) {
        symmetric_rows(w);
        return;
      }
    }
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
          wall_rows(w, buf, i0, i1);
        }
      });
      w.pair_thread_seconds[static_cast<std::size_t>(thread)] += omp_get_wtime() - start;
    }
#pragma omp barrier
  }

 private:
  void wall_rows(Workspace<D>& w, RowBuffer<D>& buf, std::size_t i0, std::size_t i1) const {
    for (std::size_t i = i0; i < i1; ++i) {
      const PairRow<D> row = buf.row(kernel_->fill_row(*w.verlet, i, buf, compact_walls_));
      for (const auto* t : walls_)
        if (i < row_range(t->rows(), w).second) t->row(w, i, row);
    }
  }

  // By every thread: the twin tables for this evaluation's Verlet list (it was rebuilt since they
  // were made) and the records sized for them.
  void make_twins(const Workspace<D>& w) const {
    const PairList& verlet = *w.verlet;
    const std::size_t nf = w.n_fluid;
#pragma omp single
    twins_.size(nf, verlet.pairs());
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < nf; ++i) twins_.find_upper(verlet, i);
#pragma omp single
    {
      twins_.place_records(verlet);
      twin_blocks_ = twins_.size_blocks(RowSchedule::kChunk);
      twins_complete_.store(true, std::memory_order_relaxed);
    }
#pragma omp for schedule(static) nowait
    for (std::size_t b = 0; b < twin_blocks_; ++b) twins_.find_block_deps(verlet, RowSchedule::kChunk, b);
    // Each thread the twins of an equal range of rows (the tables do not depend on the split).
    const auto threads = static_cast<std::size_t>(omp_get_num_threads()), t = static_cast<std::size_t>(omp_get_thread_num());
    if (!twins_.find_twins(verlet, nf * t / threads, nf * (t + 1) / threads))
      twins_complete_.store(false, std::memory_order_relaxed);
#pragma omp barrier
#pragma omp single
    {
      twins_.complete = twins_complete_.load(std::memory_order_relaxed);
      twins_list_ = &verlet;
      twins_rebuilds_ = w.verlet_rebuilds;
      twins_entries_ = verlet.pairs();
      twins_stale_ = false;
      records_.resize(twins_.records() * fluid_[0]->pair_record_size());
      const std::size_t blocks = (nf + RowSchedule::kChunk - 1) / RowSchedule::kChunk;
      if (ready_blocks_ < blocks) {
        ready_ = std::make_unique<std::atomic<std::uint64_t>[]>(blocks);  // value-initialised: 0, no epoch
        ready_blocks_ = blocks;
      }
    }
  }

  // Rows in chunks, each chunk in two sweeps: (A) the upper part of each of its rows into that row's
  // records, then the chunk marked ready for this evaluation; (B) each of its rows summed from
  // records: its own upper ones, just written, and for its lower part those of rows of smaller index,
  // written moments before in the same thread's ascending range (so records are read while still in
  // cache). A row whose lower part meets a chunk that is not ready yet (another thread's range, not
  // reached) is deferred: after a barrier, when every block is ready, the deferred rows of all threads
  // are shared out and summed from records. Readiness is kept per aligned block of RowSchedule::kChunk
  // rows: the fluid set starts at row 0 and the schedule cuts at multiples of kChunk, so every chunk
  // is one block (or the set's last, shorter one). It is checked once per block a chunk's rows reach.
  // Wall rows read no record and run as in full rows. Called by every thread.
  void symmetric_rows(Workspace<D>& w) const {
    constexpr std::size_t C = RowSchedule::kChunk;
    const PairList& verlet = *w.verlet;
    const PairTerm<D>* const term = fluid_[0];
    const std::size_t R = term->pair_record_size();
    const std::uint32_t* const off = verlet.offset.data();
    const std::uint32_t* const vj = verlet.j.data();
    const std::uint32_t* const up = twins_.upper.data();
    const std::uint32_t* const rec = twins_.record.data();
    const std::uint32_t* const twin = twins_.twin.data();
    const std::uint32_t* const n_deps = twins_.n_deps.data();
    const std::uint32_t* const deps = twins_.deps.data();
    double* const records = records_.data();
    std::atomic<std::uint64_t>* const ready = ready_.get();
    const std::uint64_t epoch = epoch_;
    const int thread = omp_get_thread_num();
    const double start = omp_get_wtime();
    RowBuffer<D>& buf = buffers_[static_cast<std::size_t>(thread)];
    if (thread == 0) ++symmetric_evaluations_;
    // Whether every block row i's lower part reaches is ready (its own chunk's block is).
    auto lower_ready = [=](std::size_t i) {
      bool all = true;
      for (std::uint32_t q = off[i], e = up[i]; q < e && all; ++q) all = ready[vj[q] / C].load(std::memory_order_relaxed) == epoch;
      std::atomic_thread_fence(std::memory_order_acquire);  // pairs with the release below
      return all;
    };
    auto sum_row = [&, off, up, rec, twin, records, R, term](std::size_t i) {
      term->sum_pair_records(w, i, twin + off[i], up[i] - off[i], records + static_cast<std::size_t>(rec[i]) * R,
                             off[i + 1] - up[i], records);
    };
    std::vector<std::uint32_t>& later = deferred_[static_cast<std::size_t>(thread)];
    later.clear();
    schedule_.run(thread, [&, off, vj, up, rec, twin, n_deps, deps, records, ready, epoch, R, term](int set, std::size_t i0, std::size_t i1) {
      if (set != 0) return wall_rows(w, buf, i0, i1);
      term->pair_records(w, i0, i1, off, up, vj, rec, *kernel_, records);
      assert(i0 % C == 0 && "a fluid chunk is one aligned block (RowSchedule::place)");
      const std::size_t b = i0 / C;
      ready[b].store(epoch, std::memory_order_release);
      bool block_ready = n_deps[b] != PairTwins::kNoDeps;
      for (std::uint32_t k = 0; block_ready && k < n_deps[b]; ++k)
        block_ready = ready[deps[b * PairTwins::kMaxDeps + k]].load(std::memory_order_relaxed) == epoch;
      std::atomic_thread_fence(std::memory_order_acquire);  // pairs with the release above
      for (std::size_t i = i0; i < i1; ++i) {
        // A row that waits for records of a block not reached yet (the other thread's range) is
        // summed after the schedule, when every thread has written its records.
        if (!block_ready && !lower_ready(i)) {
          later.push_back(static_cast<std::uint32_t>(i));
          continue;
        }
        // The next row's twin records lie anywhere in the records written so far (in 3D a plane of
        // particles back): ask for them while this row sums. In 1D and 2D they are a few rows of
        // cells back, still in the L2 cache, and the requests cost more than they save (docs/performance.md).
        if (D == 3 && i + 1 < i1)
          for (std::uint32_t q = off[i + 1], e = up[i + 1]; q < e; ++q)
            __builtin_prefetch(records + static_cast<std::size_t>(twin[q]) * R, 0, 3);
        sum_row(i);
      }
    });
    // The deferred rows, once every thread has written its records: shared out among the threads in
    // chunks (after mixing, many of one thread's rows wait for the other's records, and a thread left
    // alone with its own would keep the other waiting), from records: every block is ready now.
#pragma omp barrier
    const int threads = omp_get_num_threads();
    for (int k = 0; k < threads; ++k) {
      const auto owner = static_cast<std::size_t>((thread + k) % threads);
      const std::vector<std::uint32_t>& rows = deferred_[owner];
      for (;;) {
        const std::size_t r0 = deferred_next_[owner].value.fetch_add(kDeferredChunk, std::memory_order_relaxed);
        if (r0 >= rows.size()) break;
        for (std::size_t r = r0; r < std::min(rows.size(), r0 + kDeferredChunk); ++r) sum_row(rows[r]);
      }
    }
    w.pair_thread_seconds[static_cast<std::size_t>(thread)] += omp_get_wtime() - start;
#pragma omp barrier
  }

  KernelPass<D>* kernel_;  // owned by the system, which owns this pass too
  std::vector<std::unique_ptr<PairTerm<D>>> terms_;
  std::vector<const PairTerm<D>*> fluid_, walls_;  // the terms with fluid rows, with wall rows
  std::string name_;
  bool compact_fluid_ = false, compact_walls_ = false;
  mutable std::vector<RowBuffer<D>> buffers_;  // one per thread, kept between evaluations
  mutable std::vector<std::vector<std::uint32_t>> deferred_;  // per thread: rows summed after the schedule (symmetric)
  struct alignas(64) PaddedCursor {
    std::atomic<std::size_t> value{0};
  };
  mutable std::unique_ptr<PaddedCursor[]> deferred_next_;  // per thread's list: the next row to hand out
  mutable std::size_t deferred_next_size_ = 0;
  static constexpr std::size_t kDeferredChunk = 16;
  mutable RowSchedule schedule_;
  bool symmetric_form_ = false, symmetric_ = D <= 2;
  // Per aligned block of RowSchedule::kChunk fluid rows: the epoch its records were last written in.
  mutable std::unique_ptr<std::atomic<std::uint64_t>[]> ready_;
  mutable std::size_t ready_blocks_ = 0, twin_blocks_ = 0;
  mutable std::uint64_t epoch_ = 0;  // evaluations of the pass (0: none; rows start unready)
  mutable PairTwins twins_;
  mutable std::atomic<bool> twins_complete_{false};
  mutable bool twins_stale_ = true;
  mutable const PairList* twins_list_ = nullptr;  // the list the twins were made for, at its rebuild count
  mutable long twins_rebuilds_ = -1;
  mutable std::size_t twins_entries_ = 0;
  mutable std::vector<double> records_;
  mutable long symmetric_evaluations_ = 0;
};

}  // namespace sphmol
