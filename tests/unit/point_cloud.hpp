#pragma once
// A set of points with kinds in a box, as the neighbour searches take it (tests of the searches).
#include <array>
#include <vector>

#include "sphmol/core/domain.hpp"
#include "sphmol/neighbors/neighbor_search.hpp"

template <int D>
struct PointCloud {
  std::array<std::vector<double>, D> x;
  std::vector<sphmol::Kind> kind;
  sphmol::Domain<D> domain;
  sphmol::SearchInput<D> input(double radius) const {
    sphmol::SearchInput<D> in;
    for (int d = 0; d < D; ++d) in.x[d] = x[d].data();
    in.kind = kind.data();
    in.n = kind.size();
    in.domain = &domain;
    in.radius = radius;
    return in;
  }
};
