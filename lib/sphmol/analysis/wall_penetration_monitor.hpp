#pragma once
// Wall penetration of a 2D open tank [0, Lx] x [0, Ly] (walls left, right, below; the wall surfaces lie
// half a spacing inside the outermost wall particles): a fluid particle has passed a wall when it is
// below the bottom (y < 0), or beside the tank (x < 0 or x > Lx) below the top of the side walls.
// Checked at every RHS evaluation (every step and stage); counts distinct particles, and records the
// smallest distance of any fluid particle inside the tank to a wall surface. A term with no effect on
// the RHS; the dam-break case appends it.
#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "sphmol/rhs/term.hpp"

namespace sphmol {

struct WallPenetration {
  std::vector<std::uint8_t> crossed;  // per fluid particle, 1 once it has passed a wall
  long count = 0;                     // particles that ever passed a wall
  double min_gap = std::numeric_limits<double>::infinity();  // [m], over particles inside the tank
};

class WallPenetrationMonitor final : public Term<2> {
 public:
  WallPenetrationMonitor(double Lx, double Ly, std::shared_ptr<WallPenetration> state)
      : Lx_(Lx), Ly_(Ly), s_(std::move(state)) {}
  std::string_view name() const override { return "wall_penetration_monitor"; }
  // Every thread of the system's region calls apply() (Term::runs_in_team).
  bool runs_in_team() const override { return true; }
  void apply(Workspace<2>& w) const override {
    auto& s = *s_;
#pragma omp single
    s.crossed.resize(w.n_fluid, 0);
    const long n = static_cast<long>(w.n_fluid);
    const double *const xs = w.x[0].data(), *const ys = w.x[1].data();
    std::uint8_t* const crossed = s.crossed.data();
    // Every evaluation: each thread one range of the particles, its count and minimum combined after
    // it. A count and a minimum do not depend on the thread count or the order of combining, so the
    // range's gap is a simd loop, written without branches, which also notes whether any particle is
    // out; only then does a second loop over the range flag and count them (in a sound run, never).
    const double Lx = Lx_, Ly = Ly_;
    const double inf = std::numeric_limits<double>::infinity();
    double gap = inf;
    long count = 0;
    const long threads = omp_get_num_threads(), t = omp_get_thread_num();
    const long lo = n * t / threads, hi = n * (t + 1) / threads;
    std::int64_t any_out = 0;
#pragma omp simd reduction(min : gap) reduction(| : any_out)
    for (long i = lo; i < hi; ++i) {
      const double x = xs[i], y = ys[i];
      const bool beside = (x < 0.0) | (x > Lx);
      const bool out = (y < 0.0) | ((y < Ly) & beside);
      any_out |= static_cast<std::int64_t>(out);
      // The gap of a particle inside the tank (std::min({x, Lx - x, y})); +inf, which leaves the
      // minimum as it is, for the others.
      const double g = std::min(std::min(x, Lx - x), y);
      gap = std::min(gap, !out & !beside ? g : inf);
    }
    if (any_out != 0)
      for (long i = lo; i < hi; ++i) {
        const double x = xs[i], y = ys[i];
        const bool out = y < 0.0 || (y < Ly && (x < 0.0 || x > Lx));
        if (out && !crossed[i]) {
          crossed[i] = 1;
          ++count;
        }
      }
#pragma omp critical(sphmol_wall_penetration_monitor)
    {
      s.count += count;
      s.min_gap = std::min(s.min_gap, gap);
    }
#pragma omp barrier
  }

 private:
  double Lx_, Ly_;
  std::shared_ptr<WallPenetration> s_;
};

}  // namespace sphmol
