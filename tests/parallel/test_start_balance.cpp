// The first partition of a distributed system: balanced by pair work, which every rank counts for
// its own particles in its local system (owned + halo), with no search over the whole scene.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/distributed_system.hpp"
#include "sphmol/parallel/mpi_run.hpp"
#include "sphmol/parallel/rcb_partition.hpp"
#include "serial_reference.hpp"

using namespace sphmol;
using namespace sphmol::parallel;
using namespace sphmol::parallel::testing;

TEST_CASE("distributed system: the first partition balances the pair work, not the particle count",
          "[parallel][rcb][start_balance]") {
  // A dam break with three wall layers: the walls far from the water have no pairs, so cuts by
  // particle count leave the ranks' pair work unequal.
  const Communicator comm;
  const Config c = load_config(verification("dam_break.yaml"), {"discretization.spacing=0.05", "discretization.wall_layers=3"});
  const auto whole_case = make_case<2>(c);
  const auto whole = whole_case->build(c);
  const std::vector<double> y0 = whole->initial_state();
  DistributedSystem<2> split(comm, c, *whole, y0, 0.0, MpiRunPartitioner::default_tolerance, 1.2);
  // The whole scene is neither evaluated nor searched.
  CHECK(whole->evaluations_including_refreshes() == 0);
  CHECK(whole->pair_list().rebuilds() == 0);
  CHECK(split.stats().plans == 0);
  CHECK(split.stats().repartitions == 0);

  // The first evaluation's owned rows: their pair work, balanced within the tolerance plus one
  // particle's work (a cut cannot split a particle), as the partition reported it.
  std::vector<double> y = split.local_part(y0), f(split.size());
  split.rhs(0.0, y.data(), f.data());
  CHECK(split.stats().plans == 1);
  const double work = static_cast<double>(split.pair_work().first + split.owned().size());
  const double imbalance = load_imbalance(comm, work);
  const auto& rows = split.local_system().pair_list().pairs();
  std::uint64_t longest = 0;
  for (std::size_t k = 0; k + 1 < rows.offset.size(); ++k) longest = std::max<std::uint64_t>(longest, rows.offset[k + 1] - rows.offset[k]);
  const double heaviest = comm.max(1.0 + static_cast<double>(longest));
  INFO(comm.size() << " ranks: pair-work imbalance " << imbalance << ", at the partition " << split.stats().imbalance);
  CHECK(imbalance <= MpiRunPartitioner::default_tolerance + heaviest * comm.size() / comm.sum(work));
  CHECK(split.stats().imbalance == Approx(imbalance).epsilon(1e-12));
  // Every particle is owned once.
  CHECK(comm.sum(static_cast<std::uint64_t>(split.owned().size())) == whole->particles().size());
  // And the cut is not the count's: the ranks own unequal numbers of particles.
  const double count_imbalance = load_imbalance(comm, static_cast<double>(split.owned().size()));
  INFO("particle-count imbalance " << count_imbalance);
  if (comm.size() > 1) CHECK(count_imbalance > 1.1);
}
