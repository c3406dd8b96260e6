#include "sphmol/geometry/polygon_shape.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/squared_distance_2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sphmol::geometry {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

struct PolygonShape::Impl {
  CGAL::Polygon_2<K> polygon;
};

PolygonShape::PolygonShape(const std::vector<Vec<2>>& vertices) : impl_(std::make_unique<Impl>()) {
  if (vertices.size() < 3) throw std::invalid_argument("polygon: needs at least three vertices");
  for (const auto& v : vertices) impl_->polygon.push_back(K::Point_2(v[0], v[1]));
  if (!impl_->polygon.is_simple()) throw std::invalid_argument("polygon: the outline intersects itself (or repeats a vertex)");
  bounds_.lo = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  bounds_.hi = {-bounds_.lo[0], -bounds_.lo[1]};
  for (const auto& v : vertices)
    for (int d = 0; d < 2; ++d) {
      bounds_.lo[d] = std::min(bounds_.lo[d], v[d]);
      bounds_.hi[d] = std::max(bounds_.hi[d], v[d]);
    }
}

PolygonShape::~PolygonShape() = default;

double PolygonShape::signed_distance(const Vec<2>& p) const {
  const K::Point_2 q(p[0], p[1]);
  double d2 = std::numeric_limits<double>::infinity();
  for (auto e = impl_->polygon.edges_begin(); e != impl_->polygon.edges_end(); ++e)
    d2 = std::min(d2, CGAL::to_double(CGAL::squared_distance(*e, q)));
  const double d = std::sqrt(d2);
  switch (impl_->polygon.bounded_side(q)) {
    case CGAL::ON_BOUNDED_SIDE: return signed_by_side(d, true);
    case CGAL::ON_BOUNDARY: return 0.0;
    default: return signed_by_side(d, false);
  }
}

}  // namespace sphmol::geometry
