#pragma once
// A half-space: the points on the side of a plane (a line in 2D) away from which `normal` points,
// {p : (p - point) . n < 0} with n the unit outward normal. Unbounded: its bounds are infinite except
// along an axis-aligned normal, so it is used cut by other shapes (an intersection) or by the domain
// box, as the scene builder does for every fill.
#include <limits>
#include <stdexcept>

#include "sphmol/geometry/shape.hpp"

namespace sphmol::geometry {

template <int D>
class HalfSpaceShape final : public Shape<D> {
 public:
  HalfSpaceShape(const Vec<D>& point, const Vec<D>& outward_normal) : p_(point) {
    const double len = norm<D>(outward_normal);
    if (!(len > 0.0)) throw std::invalid_argument("plane: the normal must not be zero");
    n_ = (1.0 / len) * outward_normal;
  }
  // Exact: the distance to the plane, signed.
  double signed_distance(const Vec<D>& q) const override { return dot<D>(q - p_, n_); }
  Bounds<D> bounds() const override {
    constexpr double inf = std::numeric_limits<double>::infinity();
    Bounds<D> b;
    for (int d = 0; d < D; ++d) {
      b.lo[d] = -inf;
      b.hi[d] = inf;
    }
    // Only an axis-aligned plane bounds the region, on one side of one axis.
    int axis = -1, nonzero = 0;
    for (int d = 0; d < D; ++d)
      if (n_[d] != 0.0) ++nonzero, axis = d;
    if (nonzero == 1) (n_[axis] > 0.0 ? b.hi : b.lo)[axis] = p_[axis];
    return b;
  }

 private:
  Vec<D> p_, n_{};
};

}  // namespace sphmol::geometry
