#pragma once
// Lattices that shapes are filled on. Points sit at cell centres, origin + (i + 1/2) dx along each
// axis, so a box [0, L] with L a whole number of spacings holds exactly L/dx points per axis and none
// on its faces. The 2D hexagonal lattice shifts every other row by dx/2 with rows dx sqrt(3)/2 apart.
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sphmol/geometry/shape.hpp"

namespace sphmol::geometry {

enum class LatticeType { cubic, hexagonal };

template <int D>
struct Lattice {
  double spacing = 0.0;
  LatticeType type = LatticeType::cubic;
  Vec<D> origin{};

  // The volume (area, length) each lattice point stands for: its particle's mass is rho0 times this.
  double cell_volume() const {
    const double v = std::pow(spacing, D);
    return type == LatticeType::hexagonal ? v * std::sqrt(3.0) / 2.0 : v;
  }
  double row_spacing() const { return type == LatticeType::hexagonal ? spacing * std::sqrt(3.0) / 2.0 : spacing; }

  // Calls f(point) for every lattice point in the box `b`, in lexicographic order (last axis slowest).
  void for_each_in(const Bounds<D>& b, const std::function<void(const Vec<D>&)>& f) const {
    if (!(spacing > 0.0)) throw std::invalid_argument("lattice: spacing must be > 0");
    if (type == LatticeType::hexagonal && D != 2) throw std::invalid_argument("lattice: hexagonal is two-dimensional only");
    std::array<long, D> lo{}, hi{};
    for (int d = 0; d < D; ++d) {
      // An unbounded region (a half-space) must be cut to a box first: it holds no finite point set.
      if (!std::isfinite(b.lo[d]) || !std::isfinite(b.hi[d]))
        throw std::invalid_argument("lattice: the region to fill is unbounded (cut it to a box)");
      if (b.hi[d] < b.lo[d]) return;  // empty
      const double step = d == 1 ? row_spacing() : spacing;
      // One cell of margin: the hexagonal shift and round-off never lose a point inside b.
      lo[d] = static_cast<long>(std::floor((b.lo[d] - origin[d]) / step - 0.5)) - 1;
      hi[d] = static_cast<long>(std::ceil((b.hi[d] - origin[d]) / step - 0.5)) + 1;
    }
    std::array<long, D> i = lo;
    while (true) {
      Vec<D> p{};
      for (int d = 0; d < D; ++d) {
        const double step = d == 1 ? row_spacing() : spacing;
        double shift = 0.5;
        if (d == 0 && type == LatticeType::hexagonal && D >= 2 && (i[1] & 1)) shift = 1.0;
        p[d] = origin[d] + (static_cast<double>(i[d]) + shift) * step;
      }
      if (b.contains(p)) f(p);
      int d = 0;
      for (; d < D; ++d) {
        if (++i[d] <= hi[d]) break;
        i[d] = lo[d];
      }
      if (d == D) break;
    }
  }
};

// The lattice points strictly inside `shape` (on its surface counts as outside).
template <int D>
std::vector<Vec<D>> fill(const Shape<D>& shape, const Lattice<D>& lattice) {
  std::vector<Vec<D>> points;
  lattice.for_each_in(shape.bounds(), [&](const Vec<D>& p) {
    if (shape.signed_distance(p) < 0.0) points.push_back(p);
  });
  return points;
}

}  // namespace sphmol::geometry
