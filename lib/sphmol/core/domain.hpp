#pragma once
// The simulation box: bounds, which directions are periodic, and the faces fluid may leave through.
// A fluid particle beyond an outflow face is taken out of the run (run/outflow.hpp); beyond any other
// face of a non-periodic direction it has gone through a wall, and the run ends as blown up.
#include <array>
#include <cmath>
#include <stdexcept>

namespace sphmol {

template <int D>
struct Domain {
  std::array<double, D> lo{};
  std::array<double, D> hi{};
  std::array<bool, D> periodic{};
  // Per direction, the lower and the upper face: open to outflow (an open top, an open scene axis).
  std::array<std::array<bool, 2>, D> outflow{};

  // Whether x, along direction d, lies outside the box (never along a periodic direction), and
  // whether beyond a face of the box that is not open to outflow.
  bool outside(int d, double x) const { return !periodic[d] && (x < lo[d] || x > hi[d]); }
  bool beyond_closed_face(int d, double x) const {
    return !periodic[d] && ((x < lo[d] && !outflow[d][0]) || (x > hi[d] && !outflow[d][1]));
  }

  double length(int d) const { return hi[d] - lo[d]; }
  // 1/L in periodic directions and 0 elsewhere, so the minimum-image shift below needs no branch.
  double inv_period(int d) const { return periodic[d] ? 1.0 / length(d) : 0.0; }
  double period(int d) const { return periodic[d] ? length(d) : 0.0; }

  // Minimum-image separation; valid when every periodic length is at least twice the pair radius.
  double min_image(int d, double dx) const { return dx - period(d) * std::nearbyint(dx * inv_period(d)); }

  // Map a coordinate back into [lo, hi) in periodic directions.
  double wrap(int d, double x) const {
    if (!periodic[d]) return x;
    const double L = length(d);
    double y = x - L * std::floor((x - lo[d]) / L);
    if (y >= hi[d]) y -= L;  // guards round-off at the upper face
    return y;
  }

  void require_pair_radius(double radius) const {
    for (int d = 0; d < D; ++d)
      if (periodic[d] && length(d) < 2.0 * radius)
        throw std::invalid_argument("periodic length in direction " + std::to_string(d) +
                                    " is shorter than twice the neighbour radius (" +
                                    std::to_string(radius) + "); enlarge the domain");
  }
};

}  // namespace sphmol
