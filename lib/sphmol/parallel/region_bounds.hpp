#pragma once
// Per rank, the bounding box of the particles it owns (gathered on every rank): the region a halo
// is planned against. Tighter than the cut boxes (which are infinite at the outside of the set) and
// true at the moment it is taken, whatever the particles did since the last partition. A rank
// without particles has an empty box (lo = +inf, hi = -inf), which no particle is near.
#include <array>
#include <cstddef>
#include <vector>

#include "sphmol/geometry/vec.hpp"
#include "sphmol/parallel/communicator.hpp"

namespace sphmol::parallel {

template <int D>
std::vector<geometry::Bounds<D>> gather_owned_bounds(const Communicator& comm, const std::array<const double*, D>& x,
                                                     std::size_t n);

extern template std::vector<geometry::Bounds<1>> gather_owned_bounds<1>(const Communicator&, const std::array<const double*, 1>&,
                                                                        std::size_t);
extern template std::vector<geometry::Bounds<2>> gather_owned_bounds<2>(const Communicator&, const std::array<const double*, 2>&,
                                                                        std::size_t);
extern template std::vector<geometry::Bounds<3>> gather_owned_bounds<3>(const Communicator&, const std::array<const double*, 3>&,
                                                                        std::size_t);

}  // namespace sphmol::parallel
