// The packed neighbour data of the weakly compressible row (physics/packed_neighbours.hpp): after
// every prepare() each particle's record holds exactly the numbers of the arrays it copies, and a
// gather puts pair k's record into lane k of every field (the padding lanes repeating the last pair),
// through the 256-bit transposes in 2D and the plain copies in 1D and 3D.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <omp.h>

#include "sphmol/core/domain.hpp"
#include "sphmol/core/particles.hpp"
#include "sphmol/physics/packed_neighbours.hpp"
#include "sphmol/physics/weakly_compressible_row.hpp"
#include "sphmol/rhs/workspace.hpp"

using namespace sphmol;

namespace {

// Distinct numbers per particle and field, so that a field read from the wrong particle or the
// wrong place in the record cannot match.
template <int D>
std::vector<PackedNeighbour<D>> numbered(std::size_t n) {
  std::vector<PackedNeighbour<D>> pk(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double b = 100.0 * static_cast<double>(i);
    for (int d = 0; d < D; ++d) {
      pk[i].x[d] = b + 1 + d;
      pk[i].v[d] = b + 10 + d;
    }
    pk[i].rho = b + 20;
    pk[i].q = b + 21;
    pk[i].c = b + 22;
    pk[i].vol = b + 23;
  }
  return pk;
}

template <int D>
void check_gather() {
  const auto pk = numbered<D>(200);
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::uint32_t> any(0, 199);
  for (std::uint32_t n = 1; n <= 64; ++n) {
    std::vector<std::uint32_t> j(n);
    for (auto& jk : j) jk = any(rng);
    NeighbourBlock<D, 64> out;
    gather_neighbours(pk.data(), j.data(), n, out);
    const std::uint32_t lanes = gathered_lanes(n);
    REQUIRE(lanes % 4 == 0);
    REQUIRE(lanes >= n);
    REQUIRE(lanes < n + 4);
    for (std::uint32_t k = 0; k < lanes; ++k) {
      INFO("n " << n << " lane " << k);
      const PackedNeighbour<D>& p = pk[j[k < n ? k : n - 1]];
      for (int d = 0; d < D; ++d) {
        CHECK(out.x[d][k] == p.x[d]);
        CHECK(out.v[d][k] == p.v[d]);
      }
      CHECK(out.rho[k] == p.rho);
      CHECK(out.q[k] == p.q);
      CHECK(out.c[k] == p.c);
      CHECK(out.vol[k] == p.vol);
    }
  }
}

// A few fluid and wall particles with random data in every array the row packs.
struct Scene {
  Particles<2> P;
  Domain<2> dom;
  Workspace<2> w;
  std::mt19937 rng{11};

  Scene() {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 37; ++i) P.add(Kind::Fluid, {u(rng), u(rng)}, {0, 0}, 0.5 + u(rng), 1000.0);
    for (int i = 0; i < 9; ++i) P.add(Kind::Wall, {u(rng), -0.1}, {0, 0}, 0.5 + u(rng), 1000.0, {0, 1}, 0.05);
    dom.lo = {-1.0, -1.0};
    dom.hi = {2.0, 2.0};
    w.n = P.size();
    w.n_fluid = P.n_fluid;
    w.particles = &P;
    w.domain = &dom;
    w.h = 0.1;
    w.hs.assign(w.n, w.h);
    for (int d = 0; d < 2; ++d) {
      w.x[d].resize(w.n);
      w.v[d].resize(w.n);
    }
    w.rho.resize(w.n);
    w.p.resize(w.n);
    w.c.resize(w.n);
  }
  // New numbers in every packed array, as one RHS evaluation after another.
  void update() {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (std::size_t i = 0; i < w.n; ++i) {
      for (int d = 0; d < 2; ++d) {
        w.x[d][i] = u(rng);
        w.v[d][i] = u(rng);
      }
      w.rho[i] = 1000.0 + 30.0 * u(rng);
      w.p[i] = 1e4 * u(rng);
      w.c[i] = 80.0 + u(rng);
    }
  }
};

}  // namespace

TEST_CASE("packed neighbours: a gather puts pair k's record in lane k of every field", "[physics][dam_break]") {
  check_gather<1>();
  check_gather<2>();
  check_gather<3>();
  CHECK(sizeof(PackedNeighbour<2>) == 64);
  CHECK(alignof(PackedNeighbour<2>) == 64);
}

TEST_CASE("packed neighbours: the row's records equal the arrays they pack after every update", "[physics][dam_break]") {
  Scene s;
  const WeaklyCompressibleRow<2, true> row(0.1 * 0.1 * 80.0, MonaghanPi{0.02, 0.0, 0.1});
  for (const int threads : {1, 2, 3, 1}) {
    s.update();
#pragma omp parallel num_threads(threads)
    row.prepare(s.w);
    const auto& pk = row.packed();
    REQUIRE(pk.size() == s.w.n);
    for (std::size_t i = 0; i < s.w.n; ++i) {
      INFO("threads " << threads << " particle " << i);
      for (int d = 0; d < 2; ++d) {
        CHECK(pk[i].x[d] == s.w.x[d][i]);
        CHECK(pk[i].v[d] == s.w.v[d][i]);
      }
      CHECK(pk[i].rho == s.w.rho[i]);
      CHECK(pk[i].q == s.w.p[i] / (s.w.rho[i] * s.w.rho[i]));
      CHECK(pk[i].c == s.w.c[i]);
      // m / rho for fluid neighbours only: delta-SPH diffuses between fluid particles.
      CHECK(pk[i].vol == (i < s.w.n_fluid ? s.P.mass[i] / s.w.rho[i] : 0.0));
    }
  }
}
