#pragma once
// A solid region of space, described by its signed distance: negative inside, positive outside,
// zero on the surface. Fills, wall layers and boolean combinations work through this one function,
// so a new shape is one class. The sign must be exact; the magnitude is the distance to the surface
// for the primitive shapes and a bound for their combinations (shape_algebra.hpp), which is what
// "within n spacings of the surface" needs near a single surface.
#include <algorithm>
#include <limits>
#include <memory>

#include "sphmol/geometry/vec.hpp"

namespace sphmol::geometry {

// The signed distance of a shape whose side of the surface comes from an exact predicate (CGAL's
// polygon and mesh inside tests) and whose distance d is rounded: within round-off of the surface d
// can be 0, and -0.0 would read as outside. The smallest positive double keeps the exact sign.
inline double signed_by_side(double d, bool inside) {
  const double m = std::max(d, std::numeric_limits<double>::denorm_min());
  return inside ? -m : m;
}

template <int D>
class Shape {
 public:
  virtual ~Shape() = default;
  virtual double signed_distance(const Vec<D>& p) const = 0;
  // A box that holds every inside point (need not be tight).
  virtual Bounds<D> bounds() const = 0;

  bool contains(const Vec<D>& p) const { return signed_distance(p) < 0.0; }

  // The outward unit normal of the surface nearest to p: the gradient of the signed distance, by
  // central differences with step `eps` (a small fraction of the lattice spacing).
  Vec<D> outward_normal(const Vec<D>& p, double eps) const {
    Vec<D> g{};
    for (int d = 0; d < D; ++d) {
      Vec<D> a = p, b = p;
      a[d] += eps;
      b[d] -= eps;
      g[d] = (signed_distance(a) - signed_distance(b)) / (2.0 * eps);
    }
    const double n = norm<D>(g);
    if (n > 0.0)
      for (int d = 0; d < D; ++d) g[d] /= n;
    return g;
  }
};

template <int D>
using ShapePtr = std::shared_ptr<const Shape<D>>;

}  // namespace sphmol::geometry
