#pragma once
// A pair list built with radius (support + skin) and reused across Runge-Kutta stages and steps
// until some particle has moved more than skin/2 from where it was at the build: then no pair can
// have come within the support unseen. The test looks at the positions each RHS evaluation is
// given, so it stays valid across rejected steps and stage positions alike.
#include <array>
#include <atomic>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "sphmol/neighbors/neighbor_search.hpp"

namespace sphmol {

template <int D>
class VerletList {
 public:
  VerletList(std::unique_ptr<NeighborSearch<D>> search, double support_radius, double skin)
      : search_(std::move(search)), support_(support_radius), skin_(skin) {}

  // True when update(in) would rebuild.
  bool stale(const SearchInput<D>& in) const {
    if (!built_) return true;
    if (kept_) return trivially_far(in);
    if (checked_ && same_check(in)) return far_.load(std::memory_order_relaxed);
    return moved_too_far(in);
  }

  // The displacement test of the next stale(in) / update(in), run by the caller's threads inside a
  // parallel region that already exists, so that it adds no region of its own per evaluation:
  // begin_check(in) by one thread before the region, check_in_team(in) by every thread once every
  // position of `in` is written (after a barrier). The region's end publishes the result. A change
  // of the support or of the particle count in between discards it (update tests again).
  void begin_check(const SearchInput<D>& in) {
    checked_ = built_;
    const bool far = built_ && trivially_far(in);
    far_.store(far, std::memory_order_relaxed);
    scan_ = checked_ && !far && !kept_;  // read by every thread: all of them meet the loop, or none
    check_n_ = in.n;
    check_x_ = in.x[0];
    check_support_ = support_;
  }
  void check_in_team(const SearchInput<D>& in) {
    if (!scan_) return;  // decided without the positions
    const double limit2 = this->limit2();
    const long n = static_cast<long>(in.n);
    // moved() with the box constants and arrays in locals and the OR into an integer, so that the
    // loop vectorises; the same arithmetic (Domain::min_image's), so the same answer.
    std::array<double, D> period, inv_period;
    std::array<const double*, D> x, x0;
    for (int d = 0; d < D; ++d) {
      period[d] = in.domain->period(d);
      inv_period[d] = in.domain->inv_period(d);
      x[d] = in.x[d];
      x0[d] = x_build_[d].data();
    }
    std::int64_t far = 0;
#pragma omp for schedule(static) nowait
    for (long i = 0; i < n; ++i) {
      double r2 = 0.0;
      for (int d = 0; d < D; ++d) {
        const double dx = x[d][i] - x0[d][i];
        const double m = dx - period[d] * std::nearbyint(dx * inv_period[d]);
        r2 += m * m;
      }
      far |= static_cast<std::int64_t>(r2 > limit2);
    }
    if (far != 0) far_.store(true, std::memory_order_relaxed);
  }

  // Rebuilds if needed; returns true when it did.
  bool update(const SearchInput<D>& in) {
    const bool rebuild = stale(in);
    checked_ = false;
    if (rebuild) {
      SearchInput<D> q = in;
      q.radius = support_ + skin_;
      search_->build(q, pairs_);
      for (int d = 0; d < D; ++d) x_build_[d].resize(in.n);
      const long n = static_cast<long>(in.n);
#pragma omp parallel for schedule(static)
      for (long i = 0; i < n; ++i)
        for (int d = 0; d < D; ++d) x_build_[d][i] = in.x[d][i];
      built_ = true;
      built_support_ = support_;
      ++rebuilds_;
      return true;
    }
    return false;
  }

  // Variable smoothing length: the support radius the pairs must cover from now on. Growth since the
  // build eats into the skin (the list is rebuilt once growth plus twice the largest displacement
  // exceed it); a shrunk support leaves the list a valid superset.
  void set_support(double support_radius) { support_ = support_radius; }

  // Forces a rebuild at the next update (the particle set itself changed, e.g. ghost particles).
  void invalidate() { built_ = false; }

  // The owner of the particles tests their displacements itself and replaces the list (the whole
  // system holding it) before any particle has moved half the skin since the build: the list skips
  // its own displacement test from then on, and is rebuilt only when invalidated, when the particle
  // count changes or when the support eats the skin. A run over MPI ranks
  // (parallel/distributed_system.hpp) makes each local system anew at every halo plan, planned on
  // that same test over every rank's particles, so the local list's own test would repeat it.
  void keep_until_replaced() { kept_ = true; }

  const PairList& pairs() const { return pairs_; }
  long rebuilds() const { return rebuilds_; }
  double list_radius() const { return support_ + skin_; }
  std::string_view search_name() const { return search_->name(); }

 private:
  // A support grown by g since the build leaves skin - g for the particles' motion.
  double room() const { return skin_ - std::max(0.0, support_ - built_support_); }
  double limit2() const { return 0.25 * room() * room(); }
  // Stale whatever the positions: particles were added or removed, or the support ate the skin.
  bool trivially_far(const SearchInput<D>& in) const { return in.n != x_build_[0].size() || room() <= 0.0; }
  bool same_check(const SearchInput<D>& in) const {
    return in.n == check_n_ && in.x[0] == check_x_ && support_ == check_support_;
  }
  bool moved(const SearchInput<D>& in, long i, double limit2) const {
    double r2 = 0.0;
    for (int d = 0; d < D; ++d) {
      const double dx = in.domain->min_image(d, in.x[d][i] - x_build_[d][i]);
      r2 += dx * dx;
    }
    return r2 > limit2;
  }
  bool moved_too_far(const SearchInput<D>& in) const {
    if (trivially_far(in)) return true;
    const double limit2 = this->limit2();
    // Every evaluation tests every particle (the list is rarely stale, so an early exit seldom
    // helps): split over threads; an OR of per-particle tests is the same for any thread count.
    const long n = static_cast<long>(in.n);
    bool far = false;
#pragma omp parallel for schedule(static) reduction(|| : far)
    for (long i = 0; i < n; ++i) far |= moved(in, i, limit2);
    return far;
  }

  std::unique_ptr<NeighborSearch<D>> search_;
  double support_, skin_, built_support_ = 0.0;
  PairList pairs_;
  std::array<std::vector<double>, D> x_build_;
  bool built_ = false;
  bool kept_ = false;  // keep_until_replaced()
  long rebuilds_ = 0;
  // The test of begin_check / check_in_team: valid for check_n_ particles at support check_support_.
  bool checked_ = false, scan_ = false;
  std::atomic<bool> far_{false};
  std::size_t check_n_ = 0;
  const double* check_x_ = nullptr;
  double check_support_ = 0.0;
};

}  // namespace sphmol
