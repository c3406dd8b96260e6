// Zoltan RCB: every particle gets one rank, the ranks' weights are within the tolerance (plus one
// particle's weight, the granularity of a cut), each particle lies in its rank's cut box, the
// weights and not the counts are balanced, and a repartition after the weights changed restores
// the balance.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>

#include "particle_sets.hpp"
#include "sphmol/parallel/migration.hpp"
#include "sphmol/parallel/rcb_partition.hpp"

using namespace sphmol;
using namespace sphmol::parallel;

namespace {

constexpr double tolerance = 1.05;

// The bound a partition must meet: tolerance x mean, plus the heaviest particle (a cut cannot
// split one), as a ratio to the mean.
double allowed_imbalance(const Communicator& comm, const std::vector<double>& w) {
  const double total = comm.sum(std::accumulate(w.begin(), w.end(), 0.0));
  const double heaviest = comm.max(w.empty() ? 0.0 : *std::max_element(w.begin(), w.end()));
  return tolerance + heaviest * comm.size() / total;
}

double local_sum(const std::vector<double>& w) { return std::accumulate(w.begin(), w.end(), 0.0); }

// Partition, migrate (the weights travel as an extra array), and check the result.
template <int D>
void partition_and_check(const Communicator& comm, RcbPartitioner<D>& rcb, Particles<D>& p, std::vector<std::uint64_t>& gid,
                         std::vector<double>& w, std::size_t n_total) {
  const RcbResult<D> r = rcb.partition(test::positions(p), w.data(), gid.data(), gid.size());
  REQUIRE(r.destination.size() == gid.size());
  REQUIRE(r.boxes.size() == static_cast<std::size_t>(comm.size()));
  CHECK(std::all_of(r.destination.begin(), r.destination.end(), [&](int d) { return d >= 0 && d < comm.size(); }));
  migrate(comm, p, gid, r.destination, {&w});

  std::vector<std::uint64_t> all = comm.all_gather_v(gid);
  std::sort(all.begin(), all.end());
  std::vector<std::uint64_t> expected(n_total);
  std::iota(expected.begin(), expected.end(), std::uint64_t{0});
  CHECK(all == expected);
  CHECK(load_imbalance(comm, local_sum(w)) <= allowed_imbalance(comm, w));
  const auto& box = r.boxes[static_cast<std::size_t>(comm.rank())];
  std::size_t outside = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::array<double, D> xi{};
    for (int d = 0; d < D; ++d) xi[d] = p.x[d][i];
    outside += !box.contains(xi);
  }
  CHECK(outside == 0);
}

template <int D>
void check_weighted_partition(std::array<bool, D> periodic, double support) {
  const Communicator comm;
  const std::size_t n = 1500;
  const auto s = test::random_set<D>(n, periodic, 3);
  Particles<D> p;
  std::vector<std::uint64_t> gid;
  test::take_share(s, comm, p, gid);
  // Pair-count weights (serial rows on the whole set) plus one per particle, and ten times that
  // where x < 0.3: the ranks' particle counts must then differ.
  const PairList rows = test::serial_pairs<D>(test::positions(s.particles), s.particles.kind.data(), n, s.domain, support);
  std::vector<double> w(gid.size());
  for (std::size_t i = 0; i < gid.size(); ++i) {
    const std::size_t g = gid[i];
    w[i] = (1.0 + rows.offset[g + 1] - rows.offset[g]) * (s.particles.x[0][g] < 0.3 ? 10.0 : 1.0);
  }
  RcbPartitioner<D> rcb(comm, tolerance);
  partition_and_check(comm, rcb, p, gid, w, n);
  if (comm.size() > 1) CHECK(load_imbalance(comm, static_cast<double>(gid.size())) > 1.5);

  // The work moves: particles with x > 0.6 become five times heavier. The old decomposition is now
  // past a 1.1 threshold; a repartition brings it back within the tolerance.
  for (std::size_t i = 0; i < gid.size(); ++i)
    if (p.x[0][i] > 0.6) w[i] *= 5.0;
  if (comm.size() > 1) CHECK(load_imbalance(comm, local_sum(w)) > 1.1);
  partition_and_check(comm, rcb, p, gid, w, n);
}

}  // namespace

TEST_CASE("RCB partition: each particle once, weight balanced, particles in their cut boxes (2D, 3D)", "[parallel][rcb]") {
  check_weighted_partition<2>({false, false}, 0.06);
  check_weighted_partition<2>({true, false}, 0.06);
  check_weighted_partition<3>({false, false, true}, 0.12);
}

TEST_CASE("RCB partition: the load imbalance of a decomposition", "[parallel][rcb]") {
  const Communicator comm;
  // Rank r holds weight r + 1: the largest is P, the mean (P + 1) / 2.
  const double P = comm.size();
  CHECK(load_imbalance(comm, comm.rank() + 1.0) == Approx(2.0 * P / (P + 1.0)));
  CHECK(load_imbalance(comm, 0.0) == 1.0);
}

TEST_CASE("RCB partition: bad weights and tolerances are refused", "[parallel][rcb]") {
  const Communicator comm;
  CHECK_THROWS_WITH(RcbPartitioner<2>(comm, 1.0), Catch::Contains("above 1"));
  RcbPartitioner<2> rcb(comm, tolerance);
  const std::vector<double> x{0.1, 0.2}, y{0.3, 0.4}, w{1.0, -2.0};
  const std::vector<std::uint64_t> gid{static_cast<std::uint64_t>(2 * comm.rank()), static_cast<std::uint64_t>(2 * comm.rank() + 1)};
  CHECK_THROWS_WITH(rcb.partition({x.data(), y.data()}, w.data(), gid.data(), 2), Catch::Contains("weight"));
}
