#pragma once
// Recursive coordinate bisection of the particles over the ranks, by Zoltan (Devine et al. 2002;
// Berger and Bokhari 1987): cuts at right angles to the axes split the total weight in halves,
// recursively, until each rank has one box. A particle's weight is its share of the work: its
// pair count (the row length of the neighbour list) plus one for the per-particle updates.
// The partitioner keeps Zoltan's state between calls, so a repartition reuses the memory and the
// cuts of the last one are the cut boxes this returns.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sphmol/geometry/vec.hpp"
#include "sphmol/parallel/communicator.hpp"

struct Zoltan_Struct;

namespace sphmol::parallel {

template <int D>
struct RcbResult {
  // Per local particle: the rank that owns it after the partition.
  std::vector<int> destination;
  // Per rank: its cut box. Sides facing the outside of the particle set are infinite (the cuts
  // bound a box only where it meets another rank's).
  std::vector<geometry::Bounds<D>> boxes;
  bool changed = false;  // some particle changes rank
};

template <int D>
class RcbPartitioner {
 public:
  // imbalance_tolerance: the largest rank's weight over the mean that Zoltan aims for (> 1).
  RcbPartitioner(const Communicator& comm, double imbalance_tolerance);
  ~RcbPartitioner();
  RcbPartitioner(const RcbPartitioner&) = delete;
  RcbPartitioner& operator=(const RcbPartitioner&) = delete;

  double imbalance_tolerance() const { return tolerance_; }

  // The local particles (positions x[d][i], weights w[i] >= 0, global ids gid[i]), collectively.
  RcbResult<D> partition(const std::array<const double*, D>& x, const double* weight, const std::uint64_t* gid,
                         std::size_t n);

 private:
  Communicator comm_;
  double tolerance_;
  Zoltan_Struct* zz_ = nullptr;
};

// The largest rank's weight over the mean weight of a rank (1 for an even share; 1 when there is no
// weight at all). A decomposition is repartitioned when this passes a threshold.
double load_imbalance(const Communicator& comm, double local_weight);

extern template class RcbPartitioner<1>;
extern template class RcbPartitioner<2>;
extern template class RcbPartitioner<3>;

}  // namespace sphmol::parallel
