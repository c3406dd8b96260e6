#pragma once
// A finite circular cylinder in 3D: the points within `radius` of the segment from `a` to `b`,
// between the two end planes (flat caps).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sphmol/geometry/shape.hpp"

namespace sphmol::geometry {

class CylinderShape final : public Shape<3> {
 public:
  CylinderShape(const Vec<3>& a, const Vec<3>& b, double radius) : a_(a), r_(radius) {
    if (!(radius > 0.0)) throw std::invalid_argument("cylinder: radius must be > 0");
    const Vec<3> ab = b - a;
    length_ = norm<3>(ab);
    if (!(length_ > 0.0)) throw std::invalid_argument("cylinder: the two end points must differ");
    axis_ = (1.0 / length_) * ab;
  }
  // Exact: the signed distance of the 2D rectangle (radial distance, axial position) of half
  // extents (r, L/2), which is what a capped cylinder is in its own coordinates.
  double signed_distance(const Vec<3>& p) const override {
    const Vec<3> ap = p - a_;
    const double s = dot<3>(ap, axis_);
    const double radial = norm<3>(ap - s * axis_);
    const double qr = radial - r_, qa = std::abs(s - 0.5 * length_) - 0.5 * length_;
    const double out = std::sqrt(std::max(qr, 0.0) * std::max(qr, 0.0) + std::max(qa, 0.0) * std::max(qa, 0.0));
    return out > 0.0 ? out : std::max(qr, qa);
  }
  Bounds<3> bounds() const override {
    const Vec<3> b = a_ + length_ * axis_;
    Bounds<3> box;
    // Tight: a cap (a disc of radius r about the axis) reaches r sqrt(1 - a_d^2) along axis d.
    for (int d = 0; d < 3; ++d) {
      const double reach = r_ * std::sqrt(std::max(0.0, 1.0 - axis_[d] * axis_[d]));
      box.lo[d] = std::min(a_[d], b[d]) - reach;
      box.hi[d] = std::max(a_[d], b[d]) + reach;
    }
    return box;
  }

 private:
  Vec<3> a_, axis_{};
  double r_, length_ = 0.0;
};

}  // namespace sphmol::geometry
