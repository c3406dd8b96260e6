#include "sphmol/parallel/region_bounds.hpp"

#include <algorithm>
#include <limits>

namespace sphmol::parallel {

template <int D>
std::vector<geometry::Bounds<D>> gather_owned_bounds(const Communicator& comm, const std::array<const double*, D>& x,
                                                     std::size_t n) {
  geometry::Bounds<D> b;
  b.lo.fill(std::numeric_limits<double>::infinity());
  b.hi.fill(-std::numeric_limits<double>::infinity());
  for (int d = 0; d < D; ++d)
    for (std::size_t i = 0; i < n; ++i) {
      b.lo[d] = std::min(b.lo[d], x[d][i]);
      b.hi[d] = std::max(b.hi[d], x[d][i]);
    }
  return comm.all_gather(b);
}

template std::vector<geometry::Bounds<1>> gather_owned_bounds<1>(const Communicator&, const std::array<const double*, 1>&,
                                                                 std::size_t);
template std::vector<geometry::Bounds<2>> gather_owned_bounds<2>(const Communicator&, const std::array<const double*, 2>&,
                                                                 std::size_t);
template std::vector<geometry::Bounds<3>> gather_owned_bounds<3>(const Communicator&, const std::array<const double*, 3>&,
                                                                 std::size_t);

}  // namespace sphmol::parallel
