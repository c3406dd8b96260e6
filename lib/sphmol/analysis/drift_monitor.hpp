#pragma once
// Largest displacement of any fluid particle from its initial position, checked at every RHS
// evaluation (so every step and stage, not only output times). A monitor (rhs/monitor.hpp) whose term
// has no effect on the RHS; the hydrostatic case adds it. Positions are those the RHS sees (not
// wrapped in walled directions). Over ranks each rank takes the largest over the particles it owns,
// against their initial positions as its local system's rows carry them (WatchedRows::start), and
// combine() the largest over the ranks; a rank that has dropped the whole scene drops the whole
// scene's initial positions with it (release_whole()).
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "sphmol/rhs/monitor.hpp"

namespace sphmol {

template <int D>
class DriftMonitor final : public Monitor<D> {
  using Positions = std::array<std::vector<double>, D>;

 public:
  DriftMonitor(const Particles<D>& initial, std::shared_ptr<double> max_drift)
      : x0_(std::make_shared<Positions>()), max_(std::move(max_drift)) {
    for (int d = 0; d < D; ++d) (*x0_)[d].assign(initial.x[d].begin(), initial.x[d].begin() + initial.n_fluid);
  }
  std::unique_ptr<Term<D>> watch(const WatchedRows& rows) override {
    if (!rows.whole() && rows.start.size() != D * rows.id.size())
      throw std::invalid_argument("DriftMonitor: a local system's rows need their start positions (WatchedRows::start)");
    return std::make_unique<Watch>(x0_, max_, rows);
  }
  void combine(const RankReduction& ranks) override { *max_ = ranks.max(*max_); }
  // The whole scene's term is never evaluated after the release; its starts go (the term shares them).
  void release_whole() override {
    for (auto& c : *x0_) std::vector<double>().swap(c);
  }
  // Initial positions held for the whole scene (D per fluid particle; 0 once released).
  std::size_t starts_held() const {
    std::size_t n = 0;
    for (const auto& c : *x0_) n += c.size();
    return n;
  }

 private:
  class Watch final : public Term<D> {
   public:
    Watch(std::shared_ptr<const Positions> x0, std::shared_ptr<double> max, WatchedRows rows)
        : x0_(std::move(x0)), max_(std::move(max)), rows_(std::move(rows)) {}
    std::string_view name() const override { return "drift_monitor"; }
    void apply(Workspace<D>& w) const override {
      if (rows_.paused()) return;
      const Positions& x0 = *x0_;
      double m2 = 0.0;
      const bool whole = rows_.whole();
      for (std::size_t i = 0; i < w.n_fluid; ++i) {
        // A rank's local system: its own rows only, each against the start its row carries.
        if (!whole && !rows_.owned[i]) continue;
        const std::size_t k = whole ? (w.order ? w.order[i] : i) : 0;
        double r2 = 0.0;
        for (int d = 0; d < D; ++d) {
          const double start = whole ? x0[d][k] : rows_.start[D * i + static_cast<std::size_t>(d)];
          const double dx = w.domain->min_image(d, w.x[d][i] - start);
          r2 += dx * dx;
        }
        m2 = std::max(m2, r2);
      }
      *max_ = std::max(*max_, std::sqrt(m2));
    }

   private:
    std::shared_ptr<const Positions> x0_;
    std::shared_ptr<double> max_;
    WatchedRows rows_;
  };

  std::shared_ptr<Positions> x0_;
  std::shared_ptr<double> max_;
};

}  // namespace sphmol
