#pragma once
// How the rows of a pair pass are shared among threads. The rows [lo, hi) of each set (fluid rows,
// wall rows) are cut into one contiguous range per thread where the pairs plus a fixed per-row cost
// are shared equally: rows differ in cost (a particle deep in the fluid or by a wall has more
// neighbours than one at the free surface), and an equal count of rows left one thread 20 % more
// pair work in the dam break. A contiguous range is a compact region in the Morton order, close to
// the particles that the static per-particle loops (and the integrator, time/particle_split.hpp) give
// the same thread, so the cache lines a row writes and most of those it reads stay on that thread's
// core. Rows handed out dynamically sent half of them to the other core at every evaluation, and the
// per-particle loops after the pass took twice their 1-thread CPU time (perf, 2-thread dam break).
// Each range is eaten in chunks through an atomic cursor, and a thread done with its own ranges takes
// chunks from the others', so a thread the host slows down, or a cut the cost model misplaces, does
// not leave the other waiting. A row is written by one thread whoever takes it: results do not
// depend on the split.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>

namespace sphmol {

class RowSchedule {
 public:
  static constexpr std::size_t kChunk = 32;
  static constexpr double kRowCost = 4.0;  // fixed work per row, in pairs

  // By one thread before the rows (before the region, or in `omp single` inside it), with the team
  // size (a smaller team is fine: the ranges of absent threads are taken by the others).
  void reset(int threads, int sets) {
    const auto need = static_cast<std::size_t>(threads) * static_cast<std::size_t>(sets);
    if (need > capacity_) {
      cursors_ = std::make_unique<Cursor[]>(need);
      capacity_ = need;
    }
    threads_ = threads;
    sets_ = sets;
  }
  // Cuts rows [lo, hi) of set `set` by the CSR offsets (row i holds offset[i + 1] - offset[i] pairs).
  void place(int set, const std::uint32_t* offset, std::size_t lo, std::size_t hi) {
    const auto cost = [&](std::size_t i) { return static_cast<double>(offset[i]) + kRowCost * static_cast<double>(i); };
    Cursor* c = cursors_.get() + static_cast<std::size_t>(set) * static_cast<std::size_t>(threads_);
    std::size_t from = lo;
    for (int t = 0; t < threads_; ++t) {
      std::size_t to = hi;
      if (t + 1 < threads_) {
        // The first row whose prefix cost reaches the target (the prefix cost rises with i).
        const double target = cost(lo) + (cost(hi) - cost(lo)) * (t + 1) / threads_;
        // Binary search over [from, hi) (std::ranges over an iota view does not build with clang 14's
        // view of libstdc++ 12, which the fuzz targets use).
        std::size_t a = from, b = hi;
        while (a < b) {
          const std::size_t mid = a + (b - a) / 2;
          if (cost(mid) < target) a = mid + 1;
          else b = mid;
        }
        // Cut at a multiple of kChunk, so that every chunk of a set that starts at row 0 is one
        // aligned block of rows (symmetric pair passes mark readiness per block).
        to = std::max(from, a / kChunk * kChunk);
      }
      c[t].next.store(from, std::memory_order_relaxed);
      c[t].end = to;
      from = to;
    }
  }
  // Inside the parallel region, by every thread: rows(set, i0, i1) over the thread's own ranges, then
  // over what is left of the others'.
  template <class Rows>
  void run(int thread, const Rows& rows) {
    for (int k = 0; k < threads_; ++k) {
      const int owner = (thread + k) % threads_;
      for (int set = 0; set < sets_; ++set) {
        Cursor& c = cursors_[static_cast<std::size_t>(set * threads_ + owner)];
        for (;;) {
          // Relaxed: the rows' results are published by the barrier after the rows.
          const std::size_t i0 = c.next.fetch_add(kChunk, std::memory_order_relaxed);
          if (i0 >= c.end) break;
          rows(set, i0, std::min(i0 + kChunk, c.end));
        }
      }
    }
  }

 private:
  // One range [next, end), on its own cache line: its owner and a helper update it at the same time
  // only at the very end of the pass.
  struct alignas(64) Cursor {
    std::atomic<std::size_t> next{0};
    std::size_t end = 0;
  };
  std::unique_ptr<Cursor[]> cursors_;
  std::size_t capacity_ = 0;
  int threads_ = 1, sets_ = 1;
};

}  // namespace sphmol
