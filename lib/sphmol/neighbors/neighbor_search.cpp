#include "sphmol/neighbors/neighbor_search.hpp"

#include <stdexcept>

#include "sphmol/neighbors/all_pairs_search.hpp"
#include "sphmol/neighbors/cell_list_search.hpp"
#include "sphmol/neighbors/kdtree_search.hpp"

namespace sphmol {

template <int D>
std::unique_ptr<NeighborSearch<D>> make_neighbor_search(std::string_view name) {
  if (name == "kdtree") return std::make_unique<KdTreeSearch<D>>();
  if (name == "all_pairs") return std::make_unique<AllPairsSearch<D>>();
  if (name == "cell_list") return std::make_unique<CellListSearch<D>>();
  throw std::invalid_argument("unknown neighbour search '" + std::string(name) + "' (known: kdtree, cell_list, all_pairs)");
}

template std::unique_ptr<NeighborSearch<1>> make_neighbor_search<1>(std::string_view);
template std::unique_ptr<NeighborSearch<2>> make_neighbor_search<2>(std::string_view);
template std::unique_ptr<NeighborSearch<3>> make_neighbor_search<3>(std::string_view);

}  // namespace sphmol
