// The kd-tree search must give exactly the pair sets of the all-pairs reference: random, lattice and
// periodic particle sets in 1D/2D/3D, with wall particles (wall-wall pairs are never listed).
#include <catch2/catch.hpp>

#include <random>

#include "sphmol/neighbors/all_pairs_search.hpp"
#include "sphmol/neighbors/cell_list_search.hpp"
#include "sphmol/neighbors/kdtree_search.hpp"
#include "sphmol/neighbors/verlet_list.hpp"
#include "point_cloud.hpp"

using namespace sphmol;

namespace {

template <int D>
using Cloud = PointCloud<D>;

template <int D>
Cloud<D> random_cloud(std::size_t n, bool periodic, double wall_fraction, unsigned seed) {
  Cloud<D> c;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int d = 0; d < D; ++d) {
    c.domain.lo[d] = 0.0;
    c.domain.hi[d] = 1.0;
    c.domain.periodic[d] = periodic;
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < D; ++d) c.x[d].push_back(u(rng));
    c.kind.push_back(u(rng) < wall_fraction ? Kind::Wall : Kind::Fluid);
  }
  return c;
}

template <int D>
Cloud<D> lattice_cloud(int per_side, bool periodic) {
  Cloud<D> c;
  const double dx = 1.0 / per_side;
  for (int d = 0; d < D; ++d) {
    c.domain.lo[d] = 0.0;
    c.domain.hi[d] = 1.0;
    c.domain.periodic[d] = periodic;
  }
  int total = 1;
  for (int d = 0; d < D; ++d) total *= per_side;
  for (int k = 0; k < total; ++k) {
    for (int d = 0, kk = k; d < D; ++d, kk /= per_side) c.x[d].push_back((kk % per_side + 0.5) * dx);
    c.kind.push_back(k % 7 == 0 ? Kind::Wall : Kind::Fluid);
  }
  return c;
}

template <int D>
void require_same_pairs(const Cloud<D>& c, double radius) {
  PairList ref, tree, cells;
  AllPairsSearch<D>().build(c.input(radius), ref);
  KdTreeSearch<D>().build(c.input(radius), tree);
  CellListSearch<D>().build(c.input(radius), cells);
  REQUIRE(ref.offset == tree.offset);
  REQUIRE(ref.j == tree.j);
  REQUIRE(ref.offset == cells.offset);
  REQUIRE(ref.j == cells.j);
  // Never a pair of two wall particles; every pair listed from both sides.
  std::size_t walls_only = 0;
  for (std::size_t i = 0; i < ref.rows(); ++i)
    for (auto k = ref.offset[i]; k < ref.offset[i + 1]; ++k)
      if (c.kind[i] == Kind::Wall && c.kind[ref.j[k]] == Kind::Wall) ++walls_only;
  CHECK(walls_only == 0);
  CHECK(ref.pairs() > 0);
  // The rows' lengths without the pairs (what a partition by pair count reads), from every search;
  // the cell list counts in its own pass, then builds its list again as before.
  std::vector<std::uint32_t> lengths(ref.rows());
  for (std::size_t i = 0; i < ref.rows(); ++i) lengths[i] = ref.offset[i + 1] - ref.offset[i];
  CellListSearch<D> counting;
  CHECK(counting.row_lengths(c.input(radius)) == lengths);
  PairList again;
  counting.build(c.input(radius), again);
  CHECK(again.offset == ref.offset);
  CHECK(again.j == ref.j);
  CHECK(KdTreeSearch<D>().row_lengths(c.input(radius)) == lengths);
  CHECK(AllPairsSearch<D>().row_lengths(c.input(radius)) == lengths);
}

}  // namespace

TEMPLATE_TEST_CASE_SIG("kd-tree, cell list and all-pairs give identical pair sets", "[neighbors]", ((int D), D), 1, 2, 3) {
  const double radius = D == 1 ? 0.03 : D == 2 ? 0.09 : 0.2;
  SECTION("random, open box") { require_same_pairs(random_cloud<D>(D == 3 ? 600 : 800, false, 0.2, 1), radius); }
  SECTION("random, periodic box") { require_same_pairs(random_cloud<D>(D == 3 ? 600 : 800, true, 0.2, 2), radius); }
  SECTION("lattice, periodic box, radius on lattice distances") {
    // Radius exactly 2 spacings: particles at exactly that distance are on the boundary of the
    // support and must be excluded by both searches alike.
    const int n = D == 3 ? 10 : 20;
    require_same_pairs(lattice_cloud<D>(n, true), 2.0 / n);
  }
  SECTION("periodic box only two cells wide") { require_same_pairs(random_cloud<D>(300, true, 0.2, 5), 0.45); }
  SECTION("a particle outside the open box") {
    auto c = random_cloud<D>(400, false, 0.2, 6);
    c.x[0][0] = 1.05;  // escaped: the cell list must still find its pairs
    c.x[0][1] = 1.0 + 0.5 * radius;
    c.kind[0] = c.kind[1] = Kind::Fluid;
    require_same_pairs(c, radius);
  }
  SECTION("lattice, open box") { require_same_pairs(lattice_cloud<D>(D == 3 ? 10 : 20, false), D == 3 ? 0.25 : 0.13); }
}

TEST_CASE("periodic search rejects a box shorter than two radii", "[neighbors]") {
  auto c = random_cloud<2>(50, true, 0.0, 3);
  PairList p;
  CHECK_THROWS_WITH(KdTreeSearch<2>().build(c.input(0.6), p), Catch::Contains("periodic length"));
}

TEST_CASE("Verlet list reuses its pairs until a particle moved half the skin", "[neighbors]") {
  auto c = random_cloud<2>(400, true, 0.1, 4);
  VerletList<2> list(std::make_unique<KdTreeSearch<2>>(), 0.08, 0.02);
  CHECK(list.update(c.input(0.0)));  // first call builds
  CHECK_FALSE(list.update(c.input(0.0)));
  c.x[0][5] += 0.0099;  // less than skin/2 = 0.01
  CHECK_FALSE(list.update(c.input(0.0)));
  c.x[0][5] += 0.0002;  // now more
  CHECK(list.update(c.input(0.0)));
  CHECK(list.rebuilds() == 2);
  // The list (radius support + skin) contains every pair within the support of the moved set.
  PairList exact;
  AllPairsSearch<2>().build(c.input(0.08), exact);
  const auto& P = list.pairs();
  for (std::size_t i = 0; i < exact.rows(); ++i)
    for (auto k = exact.offset[i]; k < exact.offset[i + 1]; ++k)
      CHECK(std::binary_search(P.j.begin() + P.offset[i], P.j.begin() + P.offset[i + 1], exact.j[k]));
}

TEST_CASE("Verlet list kept by its owner skips its own displacement test", "[neighbors]") {
  // keep_until_replaced(): the owner (a run over MPI ranks) tests the displacements itself and makes
  // a new list in time; the list still rebuilds when invalidated, when the particle count changes
  // and when a grown support eats the skin.
  auto c = random_cloud<2>(400, true, 0.1, 4);
  VerletList<2> list(std::make_unique<KdTreeSearch<2>>(), 0.08, 0.02);
  list.keep_until_replaced();
  CHECK(list.update(c.input(0.0)));  // the first call builds
  c.x[0][5] += 0.05;                 // far more than skin/2
  CHECK_FALSE(list.stale(c.input(0.0)));
  CHECK_FALSE(list.update(c.input(0.0)));
  // The test run inside the caller's threads (SphSystem's gather region) decides the same.
  list.begin_check(c.input(0.0));
  list.check_in_team(c.input(0.0));
  CHECK_FALSE(list.update(c.input(0.0)));
  CHECK(list.rebuilds() == 1);
  // A list that is not kept rebuilds at the same positions: the kept one skipped a real test.
  VerletList<2> plain(std::make_unique<KdTreeSearch<2>>(), 0.08, 0.02);
  auto moved = c;
  moved.x[0][5] -= 0.05;
  CHECK(plain.update(moved.input(0.0)));
  CHECK(plain.update(c.input(0.0)));
  list.invalidate();
  CHECK(list.update(c.input(0.0)));
  CHECK(list.rebuilds() == 2);
  list.set_support(0.08 + 0.021);  // the support grew past the skin
  CHECK(list.stale(c.input(0.0)));
  CHECK(list.update(c.input(0.0)));
  list.set_support(0.08);
  c.x[0].push_back(0.5);
  c.x[1].push_back(0.5);
  c.kind.push_back(Kind::Fluid);
  CHECK(list.stale(c.input(0.0)));  // one particle more
  list.begin_check(c.input(0.0));
  list.check_in_team(c.input(0.0));
  CHECK(list.update(c.input(0.0)));
  CHECK(list.rebuilds() == 4);
}
