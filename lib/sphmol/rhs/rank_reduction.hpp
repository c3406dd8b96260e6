#pragma once
// Reductions over the processes of a run split over MPI ranks, declared without MPI (the serial
// library stays MPI-free; parallel/communicator_reduction.hpp implements them). Only exact ones: a
// minimum, a maximum and a union of lists give the same result in any order of combining.
#include <cstdint>
#include <vector>

namespace sphmol {

class RankReduction {
 public:
  virtual ~RankReduction() = default;
  // Collective: the smallest / largest of every rank's value, on every rank.
  virtual double min(double v) const = 0;
  virtual double max(double v) const = 0;
  // Collective: every rank's values, one after the other in rank order, on every rank.
  virtual std::vector<std::uint64_t> all_gather(const std::vector<std::uint64_t>& mine) const = 0;
};

}  // namespace sphmol
