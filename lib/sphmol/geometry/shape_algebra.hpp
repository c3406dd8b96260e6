#pragma once
// Boolean combinations of shapes through their signed distances (Ricci 1973's min/max
// composition): union = min, intersection = max, difference A \ B = max(d_A, -d_B). The sign is
// exact; the magnitude is exact near one surface and a bound (never too large outside) near the
// edges where surfaces meet.
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <vector>

#include "sphmol/geometry/shape.hpp"

namespace sphmol::geometry {

template <int D>
class UnionShape final : public Shape<D> {
 public:
  explicit UnionShape(std::vector<ShapePtr<D>> parts) : parts_(std::move(parts)) {}
  double signed_distance(const Vec<D>& p) const override {
    double s = std::numeric_limits<double>::infinity();
    for (const auto& q : parts_) s = std::min(s, q->signed_distance(p));
    return s;
  }
  Bounds<D> bounds() const override {
    Bounds<D> b = parts_.front()->bounds();
    for (const auto& q : parts_) {
      const Bounds<D> c = q->bounds();
      for (int d = 0; d < D; ++d) {
        b.lo[d] = std::min(b.lo[d], c.lo[d]);
        b.hi[d] = std::max(b.hi[d], c.hi[d]);
      }
    }
    return b;
  }

 private:
  std::vector<ShapePtr<D>> parts_;
};

template <int D>
class IntersectionShape final : public Shape<D> {
 public:
  IntersectionShape(ShapePtr<D> a, ShapePtr<D> b) : a_(std::move(a)), b_(std::move(b)) {}
  double signed_distance(const Vec<D>& p) const override { return std::max(a_->signed_distance(p), b_->signed_distance(p)); }
  Bounds<D> bounds() const override {
    Bounds<D> x = a_->bounds();
    const Bounds<D> y = b_->bounds();
    for (int d = 0; d < D; ++d) {
      x.lo[d] = std::max(x.lo[d], y.lo[d]);
      x.hi[d] = std::min(x.hi[d], y.hi[d]);
    }
    return x;
  }

 private:
  ShapePtr<D> a_, b_;
};

template <int D>
class DifferenceShape final : public Shape<D> {
 public:
  DifferenceShape(ShapePtr<D> a, ShapePtr<D> b) : a_(std::move(a)), b_(std::move(b)) {}
  double signed_distance(const Vec<D>& p) const override { return std::max(a_->signed_distance(p), -b_->signed_distance(p)); }
  Bounds<D> bounds() const override { return a_->bounds(); }

 private:
  ShapePtr<D> a_, b_;
};

template <int D>
ShapePtr<D> unite(std::vector<ShapePtr<D>> parts) {
  if (parts.empty()) throw std::invalid_argument("union: needs at least one shape");
  if (parts.size() == 1) return parts.front();
  return std::make_shared<UnionShape<D>>(std::move(parts));
}
template <int D>
ShapePtr<D> intersect(ShapePtr<D> a, ShapePtr<D> b) {
  return std::make_shared<IntersectionShape<D>>(std::move(a), std::move(b));
}
template <int D>
ShapePtr<D> subtract(ShapePtr<D> a, ShapePtr<D> b) {
  return std::make_shared<DifferenceShape<D>>(std::move(a), std::move(b));
}

}  // namespace sphmol::geometry
