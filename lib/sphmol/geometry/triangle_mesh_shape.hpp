#pragma once
// A closed triangle surface in 3D, read from STL, OFF, PLY or OBJ (by the file extension) through
// CGAL, which also repairs and orients the polygon soup. Inside-ness by CGAL's Side_of_triangle_mesh,
// distance by an AABB tree of the triangles.
// The file is read whole, at most kMaxMeshBytes, before CGAL parses it from memory; element counts
// that an OFF or PLY header declares are checked against the file's size first, because CGAL's OFF
// reader allocates what the header declares (a 30-byte file could ask for gigabytes).
#include <cstdint>
#include <memory>
#include <string>

#include "sphmol/geometry/shape.hpp"

namespace sphmol::geometry {

// Surface files above this are refused (a binary STL of about 5 million triangles).
inline constexpr std::uintmax_t kMaxMeshBytes = std::uintmax_t{256} << 20;  // 256 MiB

class TriangleMeshShape final : public Shape<3> {
 public:
  // Throws std::invalid_argument naming the file if it cannot be read, holds no triangles, or is not
  // a closed surface (an open surface has no inside).
  explicit TriangleMeshShape(const std::string& path);
  // The same from a file's bytes; `format` is stl, off, ply or obj, `name` names it in messages.
  TriangleMeshShape(const std::string& bytes, const std::string& format, const std::string& name);
  ~TriangleMeshShape() override;
  double signed_distance(const Vec<3>& p) const override;
  Bounds<3> bounds() const override { return bounds_; }
  std::size_t triangles() const;

 private:
  struct Impl;
  void build(const std::string& bytes, const std::string& format, const std::string& name);
  void build_unchecked(const std::string& bytes, const std::string& format, const std::string& name);
  std::unique_ptr<Impl> impl_;
  Bounds<3> bounds_;
};

}  // namespace sphmol::geometry
