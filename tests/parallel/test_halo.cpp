// Halo: after an RCB partition, the owned and halo particles of each rank contain every neighbour
// within the support that a serial search on the whole set finds for each owned particle, no
// more and no fewer, in 2D and 3D, with and without periodic axes; the plan still holds after the
// particles move by less than half the skin and only their positions are exchanged again; and a
// field exchange delivers the owners' values.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include "particle_sets.hpp"
#include "sphmol/parallel/halo.hpp"
#include "sphmol/parallel/migration.hpp"
#include "sphmol/parallel/rcb_partition.hpp"
#include "sphmol/parallel/region_bounds.hpp"

using namespace sphmol;
using namespace sphmol::parallel;

namespace {

// Owned particles and their halo as one search input.
template <int D>
struct Combined {
  std::array<std::vector<double>, D> x;
  std::vector<Kind> kind;
  std::vector<std::uint64_t> gid;
};

template <int D>
Combined<D> combine(const Communicator& comm, const Halo<D>& halo, const Particles<D>& p, const std::vector<std::uint64_t>& gid) {
  Combined<D> c;
  for (int d = 0; d < D; ++d) {
    c.x[d] = p.x[d];
    const auto h = halo.exchange(comm, p.x[d]);
    c.x[d].insert(c.x[d].end(), h.begin(), h.end());
  }
  c.kind = p.kind;
  const auto hk = halo.exchange(comm, p.kind);
  c.kind.insert(c.kind.end(), hk.begin(), hk.end());
  c.gid = gid;
  const auto hg = halo.exchange(comm, gid);
  c.gid.insert(c.gid.end(), hg.begin(), hg.end());
  return c;
}

// The number of owned particles whose neighbour ids (within `support`, on owned + halo) differ
// from the serial rows on the whole set `x_all`.
template <int D>
std::size_t rows_differing(const Combined<D>& c, std::size_t n_owned, const std::array<const double*, D>& x_all, const Kind* kind_all,
                           std::size_t n_all, const Domain<D>& domain, double support) {
  std::array<const double*, D> xc{};
  for (int d = 0; d < D; ++d) xc[d] = c.x[d].data();
  const PairList local = test::serial_pairs<D>(xc, c.kind.data(), c.gid.size(), domain, support);
  const PairList serial = test::serial_pairs<D>(x_all, kind_all, n_all, domain, support);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < n_owned; ++i) {
    std::vector<std::uint64_t> mine, reference;
    for (std::uint32_t k = local.offset[i]; k < local.offset[i + 1]; ++k) mine.push_back(c.gid[local.j[k]]);
    const std::uint64_t g = c.gid[i];
    for (std::uint32_t k = serial.offset[g]; k < serial.offset[g + 1]; ++k) reference.push_back(serial.j[k]);
    std::sort(mine.begin(), mine.end());
    differ += mine != reference;
  }
  return differ;
}

// A displacement of particle g below `bound` in length, the same on every rank.
template <int D>
std::array<double, D> displacement(std::uint64_t g, double bound) {
  std::array<double, D> dx{};
  for (int d = 0; d < D; ++d) dx[d] = bound / std::sqrt(static_cast<double>(D)) * 0.999 * std::sin(1.7 * static_cast<double>(g) + d);
  return dx;
}

template <int D>
void check_halo(std::array<bool, D> periodic, std::size_t n, double support, double skin) {
  const Communicator comm;
  auto s = test::random_set<D>(n, periodic, 7);
  Particles<D> p;
  std::vector<std::uint64_t> gid;
  test::take_share(s, comm, p, gid);
  std::vector<double> w(gid.size(), 1.0);
  RcbPartitioner<D> rcb(comm, 1.05);
  const RcbResult<D> r = rcb.partition(test::positions(p), w.data(), gid.data(), gid.size());
  migrate(comm, p, gid, r.destination);

  Halo<D> halo;
  halo.plan(comm, s.domain, gather_owned_bounds<D>(comm, test::positions(p), p.size()), test::positions(p), p.size(), support + skin);
  Combined<D> c = combine(comm, halo, p, gid);

  // No halo copy of an owned particle, none twice.
  std::set<std::uint64_t> ids(c.gid.begin(), c.gid.end());
  CHECK(ids.size() == c.gid.size());
  CHECK(rows_differing<D>(c, p.size(), test::positions(s.particles), s.particles.kind.data(), n, s.domain, support) == 0);
  // The halo is local: fewer copies than the other ranks' particles whenever there are several ranks.
  if (comm.size() > 1) CHECK(halo.size() < n - p.size());

  // Field exchange: the owners' values, from the owner the plan names.
  const auto mass = halo.exchange(comm, p.mass);
  const auto from = halo.exchange(comm, std::vector<int>(p.size(), comm.rank()));
  std::size_t wrong = 0;
  for (std::size_t k = 0; k < halo.size(); ++k) {
    const std::uint64_t g = c.gid[p.size() + k];
    wrong += mass[k] != s.particles.mass[g] || from[k] != halo.owner()[k] || from[k] == comm.rank();
  }
  CHECK(wrong == 0);

  // Every particle moves by just under skin/2 (wrapped in periodic directions); the same plan,
  // with the positions exchanged again, still gives every neighbour.
  for (std::size_t k = 0; k < n; ++k) {
    const auto dx = displacement<D>(k, 0.5 * skin);
    for (int d = 0; d < D; ++d) s.particles.x[d][k] = s.domain.wrap(d, s.particles.x[d][k] + dx[d]);
  }
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int d = 0; d < D; ++d) p.x[d][i] = s.particles.x[d][gid[i]];
  c = combine(comm, halo, p, gid);
  CHECK(rows_differing<D>(c, p.size(), test::positions(s.particles), s.particles.kind.data(), n, s.domain, support) == 0);
}

}  // namespace

TEST_CASE("halo: owned + halo hold every serial neighbour, 2D, without and with periodic axes", "[parallel][halo]") {
  check_halo<2>({false, false}, 1500, 0.06, 0.02);
  check_halo<2>({true, false}, 1500, 0.06, 0.02);
  check_halo<2>({true, true}, 1500, 0.06, 0.02);
}

TEST_CASE("halo: owned + halo hold every serial neighbour, 3D, without and with periodic axes", "[parallel][halo]") {
  check_halo<3>({false, false, false}, 2000, 0.12, 0.03);
  check_halo<3>({true, false, false}, 2000, 0.12, 0.03);
  check_halo<3>({false, true, true}, 2000, 0.12, 0.03);
}

TEST_CASE("halo: the cut boxes as regions give the same neighbours as the owned bounds", "[parallel][halo]") {
  const Communicator comm;
  auto s = test::random_set<2>(1200, {true, false}, 9);
  Particles<2> p;
  std::vector<std::uint64_t> gid;
  test::take_share(s, comm, p, gid);
  std::vector<double> w(gid.size(), 1.0);
  RcbPartitioner<2> rcb(comm, 1.05);
  const RcbResult<2> r = rcb.partition(test::positions(p), w.data(), gid.data(), gid.size());
  migrate(comm, p, gid, r.destination);
  Halo<2> halo;
  halo.plan(comm, s.domain, r.boxes, test::positions(p), p.size(), 0.08);
  const Combined<2> c = combine(comm, halo, p, gid);
  CHECK(rows_differing<2>(c, p.size(), test::positions(s.particles), s.particles.kind.data(), 1200, s.domain, 0.08) == 0);
  CHECK_THROWS_WITH(halo.plan(comm, s.domain, {}, test::positions(p), p.size(), 0.08), Catch::Contains("regions"));
}
