#pragma once
// Wall particles of a solid body: the lattice points inside the solid within `thickness` of its
// surface (thickness = layers x spacing, enough to fill the kernel support of the fluid next to it),
// each with the unit normal of the surface pointing out of the solid (into the fluid) and its depth
// below the surface. The Morris et al. (1997) wall-velocity extrapolation reads both.
//
// Box containers (the walls around a box of fluid, some faces open) have their own builder: there the
// normal and the depth are those of one face, the face the point lies deepest behind, as the
// extrapolation across a flat wall expects; the corner blocks are shared out by that rule (a point
// beyond a `priority` face, such as a moving lid, belongs to it).
#include <algorithm>
#include <optional>
#include <stdexcept>
#include <vector>

#include "sphmol/geometry/lattice.hpp"
#include "sphmol/geometry/shape.hpp"

namespace sphmol::geometry {

template <int D>
struct WallPoint {
  Vec<D> x{};
  Vec<D> normal{};   // unit, out of the solid
  double depth = 0;  // distance below the surface, > 0
  int face = -1;     // box containers: 2 d + side (side 0: the lo face, 1: the hi face); else -1
};

// `region`, if given, limits the search to a box (needed for unbounded solids such as half-spaces);
// the normals and depths are still those of the whole solid.
template <int D>
std::vector<WallPoint<D>> wall_layer(const Shape<D>& solid, const Lattice<D>& lattice, double thickness,
                                     const Bounds<D>* region = nullptr) {
  if (!(thickness > 0.0)) throw std::invalid_argument("wall layers: thickness must be > 0");
  std::vector<WallPoint<D>> points;
  const double eps = 1e-6 * lattice.spacing;
  Bounds<D> search = solid.bounds();
  if (region)
    for (int d = 0; d < D; ++d) {
      search.lo[d] = std::max(search.lo[d], region->lo[d]);
      search.hi[d] = std::min(search.hi[d], region->hi[d]);
    }
  lattice.for_each_in(search, [&](const Vec<D>& p) {
    const double sd = solid.signed_distance(p);
    if (sd < 0.0 && -sd <= thickness * (1.0 + 1e-12)) points.push_back({p, solid.outward_normal(p, eps), -sd, -1});
  });
  return points;
}

// The walls around the box [lo, hi]: lattice points outside it, no more than `thickness` beyond a
// face that is closed (open[2 d + side] false), and not beyond any open face. `lattice` should have
// its cell centres half a spacing inside the faces (origin at lo) so the walls continue the fluid's
// lattice.
template <int D>
std::vector<WallPoint<D>> box_container_walls(const Vec<D>& lo, const Vec<D>& hi, const std::array<bool, 2 * D>& open,
                                              const Lattice<D>& lattice, double thickness,
                                              std::optional<int> priority = std::nullopt) {
  if (!(thickness > 0.0)) throw std::invalid_argument("wall layers: thickness must be > 0");
  Bounds<D> region{lo, hi};
  region = region.grown(thickness);
  for (int f = 0; f < 2 * D; ++f)
    if (open[f]) (f % 2 == 0 ? region.lo : region.hi)[f / 2] = (f % 2 == 0 ? lo : hi)[f / 2];
  std::vector<WallPoint<D>> points;
  lattice.for_each_in(region, [&](const Vec<D>& p) {
    double depth[2 * D];
    bool outside = false;
    for (int d = 0; d < D; ++d) {
      depth[2 * d] = lo[d] - p[d];
      depth[2 * d + 1] = p[d] - hi[d];
      for (int s = 0; s < 2; ++s)
        if (depth[2 * d + s] > 0.0) {
          outside = true;
          if (open[2 * d + s]) return;  // beyond an open face
        }
    }
    if (!outside) return;
    for (int f = 0; f < 2 * D; ++f)
      if (depth[f] > thickness * (1.0 + 1e-12)) return;
    int face = -1;
    if (priority && depth[*priority] > 0.0) {
      face = *priority;
    } else {
      double best = 0.0;
      for (int f = 0; f < 2 * D; ++f)  // ties go to the later face
        if (depth[f] > 0.0 && depth[f] >= best) {
          best = depth[f];
          face = f;
        }
    }
    WallPoint<D> w;
    w.x = p;
    w.normal[face / 2] = face % 2 == 0 ? 1.0 : -1.0;
    w.depth = depth[face];
    w.face = face;
    points.push_back(w);
  });
  return points;
}

}  // namespace sphmol::geometry
