#pragma once
// Neighbour rows in global-id order. A rank's rows list its owned particles' neighbours by local
// index over owned + halo particles, an order that depends on the decomposition; a sum over a row
// in that order rounds differently on another rank count. Sorted by the neighbours' global ids, a
// row holds the same neighbours in the same order on any decomposition (the serial rows, when the
// serial index is the global id), so every per-particle sum comes out bit for bit the same.
//
// Terms that find a fluid row's wall pairs as the row's tail (PairRow::first_wall) need the serial
// layout, fluid before walls in index order; global ids that number the fluid first keep it.
#include <cstdint>
#include <vector>

#include "sphmol/neighbors/pair_list.hpp"

namespace sphmol::parallel {

// gid[k]: the global id of local particle k (owned, then halo), for every index the rows name.
void order_rows_by_gid(PairList& rows, const std::vector<std::uint64_t>& gid);

}  // namespace sphmol::parallel
