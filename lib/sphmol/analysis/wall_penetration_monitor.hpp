#pragma once
// Wall penetration of a 2D open tank [0, Lx] x [0, Ly] (walls left, right, below; the wall surfaces lie
// half a spacing inside the outermost wall particles): a fluid particle has passed a wall when it is
// below the bottom (y < 0), or beside the tank (x < 0 or x > Lx) below the top of the side walls.
// Checked at every RHS evaluation (every step and stage); counts distinct particles, and records the
// smallest distance of any fluid particle inside the tank to a wall surface. A monitor (rhs/monitor.hpp)
// whose term has no effect on the RHS; the dam-break case adds it. Over ranks each rank flags the
// particles it owns by their serial index, and combine() takes the union of the flags and the
// smallest gap: the serial count and gap.
#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <set>
#include <vector>

#include "sphmol/rhs/monitor.hpp"

namespace sphmol {

struct WallPenetration {
  // The fluid particles (serial indices) that have passed a wall: a set, not a flag per particle, so
  // that no rank holds an array over the whole scene for it (in a sound run it stays empty).
  std::set<std::uint64_t> crossed;
  long count = 0;                     // particles that ever passed a wall (crossed.size())
  double min_gap = std::numeric_limits<double>::infinity();  // [m], over particles inside the tank
};

class WallPenetrationMonitor final : public Monitor<2> {
 public:
  WallPenetrationMonitor(double Lx, double Ly, std::shared_ptr<WallPenetration> state) : Lx_(Lx), Ly_(Ly), s_(std::move(state)) {
    s_->crossed.clear();
    s_->count = 0;
  }
  std::unique_ptr<Term<2>> watch(const WatchedRows& rows) override { return std::make_unique<Watch>(Lx_, Ly_, s_, rows); }
  void combine(const RankReduction& ranks) override {
    const std::vector<std::uint64_t> mine(s_->crossed.begin(), s_->crossed.end());
    for (const std::uint64_t k : ranks.all_gather(mine)) s_->crossed.insert(k);
    s_->count = static_cast<long>(s_->crossed.size());
    s_->min_gap = ranks.min(s_->min_gap);
  }

 private:
  class Watch final : public Term<2> {
   public:
    Watch(double Lx, double Ly, std::shared_ptr<WallPenetration> s, WatchedRows rows)
        : Lx_(Lx), Ly_(Ly), s_(std::move(s)), rows_(std::move(rows)) {}
    std::string_view name() const override { return "wall_penetration_monitor"; }
    // Every thread of the system's region calls apply() (Term::runs_in_team).
    bool runs_in_team() const override { return true; }
    void apply(Workspace<2>& w) const override {
      if (rows_.paused()) return;  // the same on every thread
      auto& s = *s_;
      const long n = static_cast<long>(w.n_fluid);
      const double *const xs = w.x[0].data(), *const ys = w.x[1].data();
      // Every evaluation: each thread one range of the particles, its count and minimum combined after
      // it. A count and a minimum do not depend on the thread count or the order of combining, so the
      // range's gap is a simd loop, written without branches, which also notes whether any particle is
      // out; only then does a second loop over the range flag and count them (in a sound run, never).
      double gap = std::numeric_limits<double>::infinity();
      std::vector<std::uint64_t> out_now;  // this range's particles outside the tank now
      const long threads = omp_get_num_threads(), t = omp_get_thread_num();
      const long lo = n * t / threads, hi = n * (t + 1) / threads;
      std::int64_t any_out = 0;
      const std::uint8_t* const owned = rows_.owned.data();
      // A rank's local system: its own rows only (a separate loop, so the scene's stays as it was).
      if (rows_.whole()) scan<false>(xs, ys, nullptr, lo, hi, gap, any_out);
      else scan<true>(xs, ys, owned, lo, hi, gap, any_out);
      if (any_out != 0) {
        const std::uint64_t* const id = rows_.whole() ? nullptr : rows_.id.data();
        for (long i = lo; i < hi; ++i) {
          if (id && !owned[i]) continue;
          const double x = xs[i], y = ys[i];
          const bool out = y < 0.0 || (y < Ly_ && (x < 0.0 || x > Lx_));
          // Flags by serial index, which a reordered workspace or a rank's local rows are not.
          const std::size_t k = id ? id[i] : w.order ? w.order[i] : static_cast<std::size_t>(i);
          if (out) out_now.push_back(k);
        }
      }
#pragma omp critical(sphmol_wall_penetration_monitor)
      {
        s.crossed.insert(out_now.begin(), out_now.end());
        s.count = static_cast<long>(s.crossed.size());
        s.min_gap = std::min(s.min_gap, gap);
      }
#pragma omp barrier
    }

   private:
    // The smallest gap over rows [lo, hi) (Masked: the owned ones), and whether any of them is out.
    template <bool Masked>
    void scan(const double* xs, const double* ys, const std::uint8_t* owned, long lo, long hi, double& gap,
              std::int64_t& any_out) const {
      const double Lx = Lx_, Ly = Ly_;
      const double inf = std::numeric_limits<double>::infinity();
#pragma omp simd reduction(min : gap) reduction(| : any_out)
      for (long i = lo; i < hi; ++i) {
        const double x = xs[i], y = ys[i];
        const bool beside = (x < 0.0) | (x > Lx);
        const bool out = (y < 0.0) | ((y < Ly) & beside);
        // The gap of a particle inside the tank (std::min({x, Lx - x, y})); +inf, which leaves the
        // minimum as it is, for the others.
        const double g = std::min(std::min(x, Lx - x), y);
        if constexpr (Masked) {
          const bool mine = owned[i] != 0;
          any_out |= static_cast<std::int64_t>(out & mine);
          gap = std::min(gap, mine & !out & !beside ? g : inf);
        } else {
          any_out |= static_cast<std::int64_t>(out);
          gap = std::min(gap, !out & !beside ? g : inf);
        }
      }
    }

    double Lx_, Ly_;
    std::shared_ptr<WallPenetration> s_;
    WatchedRows rows_;
  };

  double Lx_, Ly_;
  std::shared_ptr<WallPenetration> s_;
};

}  // namespace sphmol
