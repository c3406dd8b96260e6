#include "sphmol/geometry/triangle_mesh_shape.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace sphmol::geometry {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

struct TriangleMeshShape::Impl {
  Mesh mesh;
  std::unique_ptr<Tree> tree;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, K, CGAL::Default, Tree>> side;
};

TriangleMeshShape::TriangleMeshShape(const std::string& path) : impl_(std::make_unique<Impl>()) {
  if (!std::filesystem::is_regular_file(path)) throw std::invalid_argument("mesh " + path + ": no such file");
  Mesh& m = impl_->mesh;
  if (!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(path, m) || m.number_of_faces() == 0)
    throw std::invalid_argument("mesh " + path + ": cannot be read as a polygon mesh (STL, OFF, PLY or OBJ)");
  if (!CGAL::is_triangle_mesh(m)) CGAL::Polygon_mesh_processing::triangulate_faces(m);
  if (!CGAL::is_closed(m)) throw std::invalid_argument("mesh " + path + ": the surface is not closed, so it has no inside");
  impl_->tree = std::make_unique<Tree>(faces(m).first, faces(m).second, m);
  impl_->tree->accelerate_distance_queries();
  impl_->side = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, K, CGAL::Default, Tree>>(*impl_->tree);
  const auto box = impl_->tree->bbox();
  bounds_.lo = {box.xmin(), box.ymin(), box.zmin()};
  bounds_.hi = {box.xmax(), box.ymax(), box.zmax()};
}

TriangleMeshShape::~TriangleMeshShape() = default;

std::size_t TriangleMeshShape::triangles() const { return impl_->mesh.number_of_faces(); }

double TriangleMeshShape::signed_distance(const Vec<3>& p) const {
  const K::Point_3 q(p[0], p[1], p[2]);
  const double d = std::sqrt(CGAL::to_double(impl_->tree->squared_distance(q)));
  switch ((*impl_->side)(q)) {
    case CGAL::ON_BOUNDED_SIDE: return -d;
    case CGAL::ON_BOUNDARY: return 0.0;
    default: return d;
  }
}

}  // namespace sphmol::geometry
