#pragma once
// The exact reductions a case's monitors combine their results with (rhs/rank_reduction.hpp), over
// the ranks of a communicator.
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/rhs/rank_reduction.hpp"

namespace sphmol::parallel {

class CommunicatorReduction final : public RankReduction {
 public:
  explicit CommunicatorReduction(const Communicator& comm) : comm_(comm) {}
  double min(double v) const override { return comm_.min(v); }
  double max(double v) const override { return comm_.max(v); }
  std::vector<std::uint64_t> all_gather(const std::vector<std::uint64_t>& mine) const override { return comm_.all_gather_v(mine); }

 private:
  Communicator comm_;
};

}  // namespace sphmol::parallel
