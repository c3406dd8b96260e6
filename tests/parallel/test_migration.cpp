// Migration: particles sent to other ranks arrive with every per-particle array they carried, the
// count and the set of global ids are conserved, and each rank's particles are fluid first in
// ascending global id. A round trip restores the original arrays exactly.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>

#include "particle_sets.hpp"
#include "sphmol/parallel/migration.hpp"

using namespace sphmol;
using namespace sphmol::parallel;

namespace {

// A destination that scatters neighbouring ids over all ranks.
int scattered_rank(std::uint64_t g, int ranks) { return static_cast<int>((g * 2654435761u + 17u) % static_cast<std::uint64_t>(ranks)); }

// Particle i of p is global particle g of s in every array.
template <int D>
bool same_particle(const Particles<D>& p, std::size_t i, const Particles<D>& s, std::size_t g) {
  bool same = p.mass[i] == s.mass[g] && p.rho[i] == s.rho[g] && p.kind[i] == s.kind[g] && p.wall_depth[i] == s.wall_depth[g] &&
              p.stationary[i] == s.stationary[g] && p.body[i] == s.body[g] && p.motion[i] == s.motion[g] &&
              p.rest_density[i] == s.rest_density[g] && p.viscosity[i] == s.viscosity[g];
  for (int d = 0; d < D; ++d)
    same = same && p.x[d][i] == s.x[d][g] && p.v[d][i] == s.v[d][g] && p.x_ref[d][i] == s.x_ref[d][g] &&
           p.wall_normal[d][i] == s.wall_normal[d][g];
  return same;
}

template <int D>
void check_scattered_migration(std::array<bool, D> periodic) {
  const Communicator comm;
  const auto s = test::random_set<D>(900, periodic, 11);
  Particles<D> p;
  std::vector<std::uint64_t> gid;
  test::take_share(s, comm, p, gid);
  std::vector<double> extra(gid.size());
  for (std::size_t i = 0; i < gid.size(); ++i) extra[i] = test::tagged(gid[i], 40);
  std::vector<int> dest(gid.size());
  for (std::size_t i = 0; i < gid.size(); ++i) dest[i] = scattered_rank(gid[i], comm.size());

  migrate(comm, p, gid, dest, {&extra});

  // Count and ids conserved: every id once over all ranks.
  CHECK(comm.sum(static_cast<std::uint64_t>(gid.size())) == 900);
  std::vector<std::uint64_t> all = comm.all_gather_v(gid);
  std::sort(all.begin(), all.end());
  std::vector<std::uint64_t> expected(900);
  std::iota(expected.begin(), expected.end(), std::uint64_t{0});
  CHECK(all == expected);
  // Each particle where it was sent, with every value it had.
  REQUIRE(p.size() == gid.size());
  REQUIRE(extra.size() == gid.size());
  std::size_t wrong_rank = 0, wrong_value = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    wrong_rank += scattered_rank(gid[i], comm.size()) != comm.rank();
    wrong_value += !same_particle(p, i, s.particles, gid[i]) || extra[i] != test::tagged(gid[i], 40);
  }
  CHECK(wrong_rank == 0);
  CHECK(wrong_value == 0);
  // Fluid first, each kind in ascending id.
  CHECK(p.n_fluid == static_cast<std::size_t>(std::count(p.kind.begin(), p.kind.end(), Kind::Fluid)));
  CHECK(std::all_of(p.kind.begin(), p.kind.begin() + static_cast<std::ptrdiff_t>(p.n_fluid), [](Kind k) { return k == Kind::Fluid; }));
  CHECK(std::is_sorted(gid.begin(), gid.begin() + static_cast<std::ptrdiff_t>(p.n_fluid)));
  CHECK(std::is_sorted(gid.begin() + static_cast<std::ptrdiff_t>(p.n_fluid), gid.end()));

  // And back: every particle to its first rank restores the share exactly.
  for (std::size_t i = 0; i < gid.size(); ++i) dest[i] = static_cast<int>(gid[i] % static_cast<std::uint64_t>(comm.size()));
  migrate(comm, p, gid, dest, {&extra});
  Particles<D> q;
  std::vector<std::uint64_t> q_gid;
  test::take_share(s, comm, q, q_gid);
  CHECK(gid == q_gid);
  CHECK(p.n_fluid == q.n_fluid);
  for (int d = 0; d < D; ++d) CHECK((p.x[d] == q.x[d] && p.v[d] == q.v[d] && p.x_ref[d] == q.x_ref[d] && p.wall_normal[d] == q.wall_normal[d]));
  CHECK((p.mass == q.mass && p.rho == q.rho && p.kind == q.kind && p.wall_depth == q.wall_depth && p.stationary == q.stationary &&
         p.body == q.body && p.motion == q.motion && p.rest_density == q.rest_density && p.viscosity == q.viscosity));
}

}  // namespace

TEST_CASE("migration: scattered destinations conserve particles, ids and every array (2D and 3D)", "[parallel][migration]") {
  check_scattered_migration<2>({false, false});
  check_scattered_migration<3>({false, true, false});
}

TEST_CASE("migration: arrays empty on every rank stay empty; a bad destination is refused on every rank", "[parallel][migration]") {
  const Communicator comm;
  const auto s = test::random_set<2>(200, {false, false}, 5);
  Particles<2> p;
  std::vector<std::uint64_t> gid;
  test::take_share(s, comm, p, gid);
  p.rest_density.clear();
  p.viscosity.clear();
  std::vector<int> dest(gid.size());
  for (std::size_t i = 0; i < gid.size(); ++i) dest[i] = scattered_rank(gid[i], comm.size());
  migrate(comm, p, gid, dest);
  CHECK(p.rest_density.empty());
  CHECK(p.viscosity.empty());
  CHECK(p.mass.size() == gid.size());

  // Rank 0 names a rank that does not exist; every rank throws, none hangs.
  std::vector<int> bad(gid.size(), comm.rank());
  if (comm.rank() == 0 && !bad.empty()) bad[0] = comm.size();
  const bool rank0_has_particles = comm.all_gather(static_cast<int>(gid.size()))[0] > 0;
  if (rank0_has_particles) CHECK_THROWS_WITH(migrate(comm, p, gid, bad), Catch::Contains("rank"));
}

TEST_CASE("migration: fluid taken out of the run (Kind::Out) travels as fluid, among the fluid", "[parallel][migration][outflow]") {
  // Its state rows are the fluid's (run/outflow.hpp): after a migration it must sit among the fluid,
  // counted in n_fluid, in ascending id, with its kind.
  const Communicator comm;
  const auto s = test::random_set<2>(300, {false, false}, 7);
  Particles<2> p;
  std::vector<std::uint64_t> gid;
  test::take_share(s, comm, p, gid);
  const auto out = [&](std::uint64_t g) { return g < s.particles.n_fluid && g % 7 == 3; };
  for (std::size_t i = 0; i < gid.size(); ++i)
    if (out(gid[i])) p.kind[i] = Kind::Out;
  std::vector<int> dest(gid.size());
  for (std::size_t i = 0; i < gid.size(); ++i) dest[i] = scattered_rank(gid[i], comm.size());
  migrate(comm, p, gid, dest);
  const auto nf = static_cast<std::ptrdiff_t>(p.n_fluid);
  CHECK(p.n_fluid == static_cast<std::size_t>(std::count_if(gid.begin(), gid.end(), [&](std::uint64_t g) { return g < s.particles.n_fluid; })));
  CHECK(std::all_of(gid.begin(), gid.begin() + nf, [&](std::uint64_t g) { return g < s.particles.n_fluid; }));
  CHECK(std::is_sorted(gid.begin(), gid.begin() + nf));
  CHECK(std::is_sorted(gid.begin() + nf, gid.end()));
  std::size_t wrong_kind = 0;
  for (std::size_t i = 0; i < gid.size(); ++i)
    wrong_kind += p.kind[i] != (out(gid[i]) ? Kind::Out : gid[i] < s.particles.n_fluid ? Kind::Fluid : Kind::Wall);
  CHECK(wrong_kind == 0);
  CHECK(comm.sum(static_cast<std::uint64_t>(std::count(p.kind.begin(), p.kind.end(), Kind::Out))) ==
        static_cast<std::uint64_t>(std::count_if(s.gid.begin(), s.gid.end(), out)));
}
