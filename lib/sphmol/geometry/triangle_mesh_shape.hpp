#pragma once
// A closed triangle surface in 3D, read from STL, OFF, PLY or OBJ (by the file extension) through
// CGAL, which also repairs and orients the polygon soup. Inside-ness by CGAL's Side_of_triangle_mesh,
// distance by an AABB tree of the triangles.
#include <memory>
#include <string>

#include "sphmol/geometry/shape.hpp"

namespace sphmol::geometry {

class TriangleMeshShape final : public Shape<3> {
 public:
  // Throws std::invalid_argument naming the file if it cannot be read, holds no triangles, or is not
  // a closed surface (an open surface has no inside).
  explicit TriangleMeshShape(const std::string& path);
  ~TriangleMeshShape() override;
  double signed_distance(const Vec<3>& p) const override;
  Bounds<3> bounds() const override { return bounds_; }
  std::size_t triangles() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  Bounds<3> bounds_;
};

}  // namespace sphmol::geometry
