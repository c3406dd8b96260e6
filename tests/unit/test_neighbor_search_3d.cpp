// Neighbour searches in 3D with periodic axes in every combination, in a box of unequal sides: the
// kd-tree, the cell list (1 and 2 threads) and the all-pairs reference give the same pair sets, and
// the reference agrees with a brute-force count written here from the minimum-image rule alone.
#include <catch2/catch.hpp>

#include <omp.h>

#include <cmath>
#include <random>

#include "sphmol/neighbors/all_pairs_search.hpp"
#include "sphmol/neighbors/cell_list_search.hpp"
#include "sphmol/neighbors/kdtree_search.hpp"
#include "point_cloud.hpp"

using namespace sphmol;

namespace {

// n random points in [0, 1] x [0, 0.8] x [0, 0.6], a fifth of them walls.
PointCloud<3> cloud(std::size_t n, std::array<bool, 3> periodic, unsigned seed) {
  PointCloud<3> c;
  const double L[3] = {1.0, 0.8, 0.6};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int d = 0; d < 3; ++d) {
    c.domain.lo[d] = 0.0;
    c.domain.hi[d] = L[d];
    c.domain.periodic[d] = periodic[d];
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) c.x[d].push_back(L[d] * u(rng));
    c.kind.push_back(u(rng) < 0.2 ? Kind::Wall : Kind::Fluid);
  }
  return c;
}

// Directed pairs within `radius`, by the nearest image in each periodic direction, fluid involved.
std::size_t brute_force_pairs(const PointCloud<3>& c, double radius) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < c.kind.size(); ++i)
    for (std::size_t j = 0; j < c.kind.size(); ++j) {
      if (i == j || (c.kind[i] == Kind::Wall && c.kind[j] == Kind::Wall)) continue;
      double r2 = 0.0;
      for (int d = 0; d < 3; ++d) {
        double s = std::abs(c.x[d][i] - c.x[d][j]);
        if (c.domain.periodic[d]) s = std::min(s, c.domain.length(d) - s);
        r2 += s * s;
      }
      count += r2 < radius * radius;
    }
  return count;
}

}  // namespace

TEST_CASE("3D searches agree with periodic axes in any combination", "[neighbors][3d]") {
  const double radius = 0.17;
  for (int combo = 0; combo < 8; ++combo) {
    const std::array<bool, 3> periodic{(combo & 1) != 0, (combo & 2) != 0, (combo & 4) != 0};
    INFO("periodic x " << periodic[0] << ", y " << periodic[1] << ", z " << periodic[2]);
    const PointCloud<3> c = cloud(700, periodic, 100 + combo);
    PairList ref, tree, cells, cells2;
    AllPairsSearch<3>().build(c.input(radius), ref);
    KdTreeSearch<3>().build(c.input(radius), tree);
    CellListSearch<3>().build(c.input(radius), cells);
    const int threads = omp_get_max_threads();
    omp_set_num_threads(2);
    CellListSearch<3>().build(c.input(radius), cells2);
    omp_set_num_threads(threads);
    REQUIRE(ref.pairs() == brute_force_pairs(c, radius));
    REQUIRE(ref.offset == tree.offset);
    REQUIRE(ref.j == tree.j);
    REQUIRE(ref.offset == cells.offset);
    REQUIRE(ref.j == cells.j);
    REQUIRE(ref.j == cells2.j);
    // A periodic axis adds the pairs across its faces: more pairs than with that axis closed.
    if (combo > 0) {
      PointCloud<3> closed = c;
      closed.domain.periodic = {false, false, false};
      PairList open_ref;
      AllPairsSearch<3>().build(closed.input(radius), open_ref);
      CHECK(ref.pairs() > open_ref.pairs());
    }
  }
}
