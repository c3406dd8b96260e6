#pragma once
// A simple polygon in 2D (vertices in either orientation). Inside-ness by CGAL's bounded_side test,
// distance to the nearest edge by CGAL's point-segment distance.
#include <memory>
#include <vector>

#include "sphmol/geometry/shape.hpp"

namespace sphmol::geometry {

class PolygonShape final : public Shape<2> {
 public:
  // Throws std::invalid_argument for fewer than three vertices or a self-intersecting outline.
  explicit PolygonShape(const std::vector<Vec<2>>& vertices);
  ~PolygonShape() override;
  double signed_distance(const Vec<2>& p) const override;
  Bounds<2> bounds() const override { return bounds_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  Bounds<2> bounds_;
};

}  // namespace sphmol::geometry
