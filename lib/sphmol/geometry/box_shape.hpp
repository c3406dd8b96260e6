#pragma once
// An axis-aligned box [lo, hi] (a rectangle in 2D, an interval in 1D).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "sphmol/geometry/shape.hpp"

namespace sphmol::geometry {

template <int D>
class BoxShape final : public Shape<D> {
 public:
  BoxShape(const Vec<D>& lo, const Vec<D>& hi) : lo_(lo), hi_(hi) {
    for (int d = 0; d < D; ++d)
      if (!(hi[d] > lo[d])) throw std::invalid_argument("box: max must exceed min in every direction");
  }
  // The exact Euclidean signed distance: outside, the distance to the nearest point of the box;
  // inside, minus the distance to the nearest face.
  double signed_distance(const Vec<D>& p) const override {
    double outside2 = 0.0, inside = -std::numeric_limits<double>::infinity();
    for (int d = 0; d < D; ++d) {
      const double c = 0.5 * (lo_[d] + hi_[d]), half = 0.5 * (hi_[d] - lo_[d]);
      const double q = std::abs(p[d] - c) - half;
      if (q > 0.0) outside2 += q * q;
      inside = std::max(inside, q);
    }
    return outside2 > 0.0 ? std::sqrt(outside2) : inside;
  }
  Bounds<D> bounds() const override { return {lo_, hi_}; }
  const Vec<D>& lo() const { return lo_; }
  const Vec<D>& hi() const { return hi_; }

 private:
  Vec<D> lo_, hi_;
};

}  // namespace sphmol::geometry
