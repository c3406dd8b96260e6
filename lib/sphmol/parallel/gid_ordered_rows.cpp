#include "sphmol/parallel/gid_ordered_rows.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sphmol::parallel {

void order_rows_by_gid(PairList& rows, const std::vector<std::uint64_t>& gid) {
  for (std::uint32_t j : rows.j)
    if (j >= gid.size())
      throw std::invalid_argument("order_rows_by_gid: neighbour " + std::to_string(j) + " has no global id (" +
                                  std::to_string(gid.size()) + " given)");
  for (std::size_t i = 0; i < rows.rows(); ++i)
    std::sort(rows.j.begin() + rows.offset[i], rows.j.begin() + rows.offset[i + 1],
              [&](std::uint32_t a, std::uint32_t b) { return gid[a] < gid[b]; });
}

}  // namespace sphmol::parallel
