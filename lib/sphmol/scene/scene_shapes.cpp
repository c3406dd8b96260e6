#include "sphmol/scene/scene_shapes.hpp"

#include <stdexcept>

#include "sphmol/config/config.hpp"
#include "sphmol/geometry/box_shape.hpp"
#include "sphmol/geometry/cylinder_shape.hpp"
#include "sphmol/geometry/half_space_shape.hpp"
#include "sphmol/geometry/polygon_shape.hpp"
#include "sphmol/geometry/shape_algebra.hpp"
#include "sphmol/geometry/sphere_shape.hpp"
#include "sphmol/geometry/triangle_mesh_shape.hpp"

namespace sphmol {

namespace {

template <int D>
geometry::Vec<D> vec(const std::vector<double>& v) {
  geometry::Vec<D> out{};
  for (int d = 0; d < D; ++d) out[d] = v.at(static_cast<std::size_t>(d));
  return out;
}

template <int D>
geometry::ShapePtr<D> make(const ShapeSpec& s) {
  using namespace geometry;
  const std::string& t = s.type;
  if (t == "box") return std::make_shared<BoxShape<D>>(vec<D>(s.lo), vec<D>(s.hi));
  if (t == "sphere") return std::make_shared<SphereShape<D>>(vec<D>(s.centre), s.radius);
  if (t == "plane") return std::make_shared<HalfSpaceShape<D>>(vec<D>(s.point), vec<D>(s.normal));
  if (t == "union" || t == "intersection" || t == "difference") {
    std::vector<ShapePtr<D>> parts;
    for (const auto& p : s.shapes) parts.push_back(make_shape<D>(p));
    if (t == "union") return unite<D>(parts);
    ShapePtr<D> acc = parts.front();
    if (t == "intersection") {
      for (std::size_t i = 1; i < parts.size(); ++i) acc = intersect<D>(acc, parts[i]);
      return acc;
    }
    std::vector<ShapePtr<D>> rest(parts.begin() + 1, parts.end());
    return subtract<D>(acc, unite<D>(rest));
  }
  if constexpr (D == 2) {
    if (t == "polygon") {
      std::vector<Vec<2>> v;
      for (const auto& p : s.vertices) v.push_back({p.at(0), p.at(1)});
      return std::make_shared<PolygonShape>(v);
    }
  }
  if constexpr (D == 3) {
    if (t == "cylinder") return std::make_shared<CylinderShape>(vec<3>(s.start), vec<3>(s.end), s.radius);
    if (t == "mesh") return std::make_shared<TriangleMeshShape>(s.file);
  }
  throw std::invalid_argument("the shape type '" + t + "' does not exist in " + std::to_string(D) + "D");
}

}  // namespace

template <int D>
geometry::ShapePtr<D> make_shape(const ShapeSpec& spec) {
  try {
    return make<D>(spec);
  } catch (const ConfigError&) {
    throw;
  } catch (const std::exception& e) {
    throw ConfigError(spec.where + ": " + e.what());
  }
}

template geometry::ShapePtr<2> make_shape<2>(const ShapeSpec&);
template geometry::ShapePtr<3> make_shape<3>(const ShapeSpec&);

}  // namespace sphmol
