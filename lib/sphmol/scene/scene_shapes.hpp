#pragma once
// The geometry-kit shape (geometry/*) a ShapeSpec describes. The reader has already checked the
// keys and the dimension; what only the kit can tell (a self-intersecting polygon, a mesh that is not
// closed) is a ConfigError at the shape's line.
#include "sphmol/geometry/shape.hpp"
#include "sphmol/scene/scene_spec.hpp"

namespace sphmol {

template <int D>
geometry::ShapePtr<D> make_shape(const ShapeSpec& spec);

}  // namespace sphmol
