#pragma once
// A pair list built with radius (support + skin) and reused across Runge-Kutta stages and steps
// until some particle has moved more than skin/2 from where it was at the build: then no pair can
// have come within the support unseen. The test looks at the positions each RHS evaluation is
// given, so it stays valid across rejected steps and stage positions alike.
#include <array>
#include <algorithm>
#include <cmath>
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
  bool stale(const SearchInput<D>& in) const { return !built_ || moved_too_far(in); }

  // Rebuilds if needed; returns true when it did.
  bool update(const SearchInput<D>& in) {
    if (stale(in)) {
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

  const PairList& pairs() const { return pairs_; }
  long rebuilds() const { return rebuilds_; }
  double list_radius() const { return support_ + skin_; }
  std::string_view search_name() const { return search_->name(); }

 private:
  bool moved_too_far(const SearchInput<D>& in) const {
    // A support grown by g since the build leaves skin - g for the particles' motion.
    if (in.n != x_build_[0].size()) return true;  // particles were added or removed
    const double room = skin_ - std::max(0.0, support_ - built_support_);
    if (room <= 0.0) return true;
    const double limit2 = 0.25 * room * room;
    // Every evaluation tests every particle (the list is rarely stale, so an early exit seldom
    // helps): split over threads; an OR of per-particle tests is the same for any thread count.
    const long n = static_cast<long>(in.n);
    bool far = false;
#pragma omp parallel for schedule(static) reduction(|| : far)
    for (long i = 0; i < n; ++i) {
      double r2 = 0.0;
      for (int d = 0; d < D; ++d) {
        const double dx = in.domain->min_image(d, in.x[d][i] - x_build_[d][i]);
        r2 += dx * dx;
      }
      far |= r2 > limit2;
    }
    return far;
  }

  std::unique_ptr<NeighborSearch<D>> search_;
  double support_, skin_, built_support_ = 0.0;
  PairList pairs_;
  std::array<std::vector<double>, D> x_build_;
  bool built_ = false;
  long rebuilds_ = 0;
};

}  // namespace sphmol
