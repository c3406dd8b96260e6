#pragma once
// A ball: a circle (disc) in 2D, a sphere in 3D.
#include <stdexcept>

#include "sphmol/geometry/shape.hpp"

namespace sphmol::geometry {

template <int D>
class SphereShape final : public Shape<D> {
 public:
  SphereShape(const Vec<D>& centre, double radius) : c_(centre), r_(radius) {
    if (!(radius > 0.0)) throw std::invalid_argument("sphere: radius must be > 0");
  }
  double signed_distance(const Vec<D>& p) const override { return norm<D>(p - c_) - r_; }
  Bounds<D> bounds() const override {
    Bounds<D> b{c_, c_};
    return b.grown(r_);
  }

 private:
  Vec<D> c_;
  double r_;
};

}  // namespace sphmol::geometry
