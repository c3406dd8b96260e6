// The cell-list build and the Verlet staleness test run in parallel (neighbors/cell_list_search.cpp,
// neighbors/verlet_list.hpp); their results must not depend on the thread count. Particle sets big
// enough that every thread gets many rows, clustered like a dam-break column (dense block, wall
// layer, empty cells, a few stray particles) and stored in shuffled order, so that rows gather
// candidates from cells in no particular index order.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <omp.h>
#include <random>

#include "sphmol/neighbors/all_pairs_search.hpp"
#include "sphmol/neighbors/cell_list_search.hpp"
#include "sphmol/neighbors/verlet_list.hpp"
#include "point_cloud.hpp"

using namespace sphmol;

namespace {

template <int D>
using Column = PointCloud<D>;

// Box [0, 1]^D: fluid on a jittered lattice of spacing dx filling [0, 0.4] in direction 0 and
// [0, 0.6] in the others, one wall layer at x_{D-1} = dx/2 across the box, and 50 fluid particles
// spread at random over the whole box.
template <int D>
Column<D> column(double dx, bool periodic, unsigned seed) {
  Column<D> c;
  for (int d = 0; d < D; ++d) {
    c.domain.lo[d] = 0.0;
    c.domain.hi[d] = 1.0;
    c.domain.periodic[d] = periodic;
  }
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::array<int, D> per;
  int total = 1;
  for (int d = 0; d < D; ++d) total *= per[d] = static_cast<int>((d == 0 ? 0.4 : 0.6) / dx);
  for (int k = 0; k < total; ++k) {
    int kk = k;
    for (int d = 0; d < D; ++d) {
      const int id = kk % per[d];
      kk /= per[d];
      c.x[d].push_back((id + 1.0 + 0.2 * (u(rng) - 0.5)) * dx);
    }
    c.kind.push_back(Kind::Fluid);
  }
  // Wall layer along the bottom (direction D - 1) over the whole box width.
  int wall = 1;
  for (int d = 0; d + 1 < D; ++d) wall *= static_cast<int>(1.0 / dx);
  for (int k = 0; k < wall; ++k) {
    int kk = k;
    for (int d = 0; d + 1 < D; ++d) {
      c.x[d].push_back((kk % static_cast<int>(1.0 / dx) + 0.5) * dx);
      kk /= static_cast<int>(1.0 / dx);
    }
    c.x[D - 1].push_back(0.5 * dx);
    c.kind.push_back(Kind::Wall);
  }
  for (int k = 0; k < 50; ++k) {
    for (int d = 0; d < D; ++d) c.x[d].push_back(u(rng));
    c.kind.push_back(Kind::Fluid);
  }
  // Shuffled storage order.
  std::vector<std::size_t> perm(c.kind.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  Column<D> s = c;
  for (std::size_t i = 0; i < perm.size(); ++i) {
    for (int d = 0; d < D; ++d) s.x[d][i] = c.x[d][perm[i]];
    s.kind[i] = c.kind[perm[i]];
  }
  return s;
}

struct ThreadCount {  // restores the OpenMP default on scope exit
  int saved = omp_get_max_threads();
  explicit ThreadCount(int t) { omp_set_num_threads(t); }
  ~ThreadCount() { omp_set_num_threads(saved); }
};

}  // namespace

TEMPLATE_TEST_CASE_SIG("the cell list equals all-pairs for 1 to 5 threads on a clustered set", "[neighbors][threads]",
                       ((int D), D), 1, 2, 3) {
  // Fluid particles: 1D 2,400, 2D 2,904, 3D 1,764; radius 2.5 spacings.
  const double dx = D == 1 ? 1.0 / 6000 : D == 2 ? 1.0 / 110 : 1.0 / 24;
  for (const bool periodic : {false, true}) {
    INFO("periodic " << periodic);
    const auto c = column<D>(dx, periodic, 7 + D);
    const double radius = 2.5 * dx;
    PairList ref;
    AllPairsSearch<D>().build(c.input(radius), ref);
    REQUIRE(ref.pairs() > 3 * ref.rows());  // dense: the comparison is not vacuous
    CellListSearch<D> cells;  // one object for every thread count: its buffers are reused
    for (const int threads : {1, 2, 3, 5, 2}) {
      INFO("threads " << threads);
      ThreadCount tc(threads);
      PairList out;
      out.j.assign(7, 42u);  // leftovers from an earlier list must not survive
      cells.build(c.input(radius), out);
      REQUIRE(out.offset == ref.offset);
      REQUIRE(out.j == ref.j);
    }
  }
}

TEST_CASE("the Verlet staleness test gives the same answer for any thread count", "[neighbors][threads]") {
  auto c = column<2>(1.0 / 110, false, 3);
  const std::size_t last = c.kind.size() - 1;  // in the last thread's block for any split
  for (const int threads : {1, 2, 3}) {
    INFO("threads " << threads);
    ThreadCount tc(threads);
    auto moved = c;
    VerletList<2> list(std::make_unique<CellListSearch<2>>(), 0.02, 0.004);
    CHECK(list.update(moved.input(0.0)));
    moved.x[0][last] += 0.00199;  // less than skin/2 = 0.002
    CHECK_FALSE(list.stale(moved.input(0.0)));
    moved.x[1][last] += 0.0005;  // now more
    CHECK(list.stale(moved.input(0.0)));
    CHECK(list.update(moved.input(0.0)));
    CHECK_FALSE(list.stale(moved.input(0.0)));  // the build positions were copied in full
    moved.x[0][0] -= 0.0021;                       // the first thread's block
    CHECK(list.stale(moved.input(0.0)));
  }
}

TEST_CASE("the Verlet staleness test run inside the caller's parallel region equals the one on its own",
          "[neighbors][threads]") {
  auto c = column<2>(1.0 / 110, false, 3);
  const std::size_t last = c.kind.size() - 1;
  // begin_check by one thread, check_in_team by every thread of a region, then stale() / update().
  auto team_check = [](VerletList<2>& list, const SearchInput<2>& in) {
    list.begin_check(in);
#pragma omp parallel
    list.check_in_team(in);
  };
  for (const int threads : {1, 2, 3}) {
    INFO("threads " << threads);
    ThreadCount tc(threads);
    auto moved = c;
    VerletList<2> list(std::make_unique<CellListSearch<2>>(), 0.02, 0.004);
    team_check(list, moved.input(0.0));
    CHECK(list.stale(moved.input(0.0)));  // never built
    CHECK(list.update(moved.input(0.0)));
    moved.x[0][last] += 0.00199;  // less than skin/2 = 0.002
    team_check(list, moved.input(0.0));
    CHECK_FALSE(list.stale(moved.input(0.0)));
    CHECK_FALSE(list.update(moved.input(0.0)));
    moved.x[1][last] += 0.0005;  // now more, in the last thread's block
    team_check(list, moved.input(0.0));
    CHECK(list.stale(moved.input(0.0)));
    const long before = list.rebuilds();
    CHECK(list.update(moved.input(0.0)));
    CHECK(list.rebuilds() == before + 1);
    moved.x[0][0] -= 0.0021;  // the first thread's block
    team_check(list, moved.input(0.0));
    CHECK(list.stale(moved.input(0.0)));
    // A support that grows after the check eats the skin: the check is discarded, not trusted.
    CHECK(list.update(moved.input(0.0)));
    moved.x[0][last] += 0.0015;
    team_check(list, moved.input(0.0));
    CHECK_FALSE(list.stale(moved.input(0.0)));
    list.set_support(0.0235);  // room 0.0005, so a move of 0.00025 is too far
    CHECK(list.stale(moved.input(0.0)));
    CHECK(list.update(moved.input(0.0)));
  }
}
