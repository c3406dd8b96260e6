#pragma once
// The run loop's view of a run over MPI ranks (run/partitioned_run.hpp), made from the whole scene:
// a DistributedSystem for the integrator, this rank's part of the state, the whole state gathered
// at output times, and the health check over ranks. Configurations the distributed system does not
// support yet are refused with a ConfigError naming the key, on every rank alike.
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/run/partitioned_run.hpp"

namespace sphmol::parallel {

class MpiRunPartitioner final : public RunPartitioner {
 public:
  // imbalance_tolerance (> 1): the partition's aim for the largest rank's pair work over the mean.
  // rebalance_threshold (>= 1): the imbalance past which the particles are partitioned again
  // (checked when the halo is planned again).
  static constexpr double default_tolerance = 1.05;
  MpiRunPartitioner(const Communicator& comm, double imbalance_tolerance, double rebalance_threshold);

  bool root() const override { return comm_.rank() == 0; }
  SceneShare share() const override;
  PieceCollectives collectives() const override;
  std::unique_ptr<PartitionedRun<1>> partition(const Config& config, const SphSystem<1>& whole,
                                               const std::vector<double>& y0, double t0,
                                               const std::function<void()>& scene_read = {}) const override;
  std::unique_ptr<PartitionedRun<2>> partition(const Config& config, const SphSystem<2>& whole,
                                               const std::vector<double>& y0, double t0,
                                               const std::function<void()>& scene_read = {}) const override;
  std::unique_ptr<PartitionedRun<3>> partition(const Config& config, const SphSystem<3>& whole,
                                               const std::vector<double>& y0, double t0,
                                               const std::function<void()>& scene_read = {}) const override;

 private:
  template <int D>
  std::unique_ptr<PartitionedRun<D>> make(const Config& config, const SphSystem<D>& whole, const std::vector<double>& y0,
                                          double t0, const std::function<void()>& scene_read) const;

  Communicator comm_;
  double tolerance_, rebalance_threshold_;
};

}  // namespace sphmol::parallel
