#pragma once
// Wall penetration of a 2D open tank [0, Lx] x [0, Ly] (walls left, right, below; the wall surfaces lie
// half a spacing inside the outermost wall particles): a fluid particle has passed a wall when it is
// below the bottom (y < 0), or beside the tank (x < 0 or x > Lx) below the top of the side walls.
// Checked at every RHS evaluation (every step and stage); counts distinct particles, and records the
// smallest distance of any fluid particle inside the tank to a wall surface. A term with no effect on
// the RHS; the dam-break case appends it.
#include <algorithm>
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
  void apply(Workspace<2>& w) const override {
    auto& s = *s_;
    s.crossed.resize(w.n_fluid, 0);
    double gap = s.min_gap;
    for (std::size_t i = 0; i < w.n_fluid; ++i) {
      const double x = w.x[0][i], y = w.x[1][i];
      const bool out = y < 0.0 || (y < Ly_ && (x < 0.0 || x > Lx_));
      if (out && !s.crossed[i]) {
        s.crossed[i] = 1;
        ++s.count;
      }
      if (!out && x >= 0.0 && x <= Lx_) gap = std::min(gap, std::min({x, Lx_ - x, y}));
    }
    s.min_gap = gap;
  }

 private:
  double Lx_, Ly_;
  std::shared_ptr<WallPenetration> s_;
};

}  // namespace sphmol
