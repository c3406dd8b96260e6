// A distributed evaluation of the continuity density rate (physics/continuity_density.hpp) on a
// dam-break-like lattice (a fluid column in a tank of three wall layers): partitioned by RCB with
// pair-count weights, owned + halo rows ordered by global id, it gives every particle the rate of
// the serial evaluation bit for bit, on any number of ranks.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

#include "particle_sets.hpp"
#include "sphmol/kernels/wendland_c2.hpp"
#include "sphmol/parallel/gid_ordered_rows.hpp"
#include "sphmol/parallel/halo.hpp"
#include "sphmol/parallel/migration.hpp"
#include "sphmol/parallel/rcb_partition.hpp"
#include "sphmol/parallel/region_bounds.hpp"
#include "sphmol/physics/continuity_density.hpp"
#include "sphmol/rhs/pair_row.hpp"

using namespace sphmol;
using namespace sphmol::parallel;

namespace {

constexpr double spacing = 0.01, h = 1.3 * spacing, support = WendlandC2Kernel<2>::support * h, skin = 0.3 * h;

// A 0.2 m x 0.4 m column at the left of a 0.8 m x 0.5 m tank, walls three layers deep below and at
// the sides, positions perturbed by a tenth of the spacing and velocities a smooth field: global id
// = serial index, fluid first.
test::GlobalSet<2> column_in_tank() {
  test::GlobalSet<2> s;
  s.domain.lo = {-3 * spacing, -3 * spacing};
  s.domain.hi = {0.8 + 3 * spacing, 0.5};
  auto add = [&](Kind k, double x, double y) {
    const double g = static_cast<double>(s.gid.size());
    const std::array<double, 2> pos{x + 0.1 * spacing * std::sin(3.1 * g), y + 0.1 * spacing * std::cos(1.7 * g)};
    const std::array<double, 2> vel = k == Kind::Fluid ? std::array<double, 2>{std::sin(7 * x + 3 * y), std::cos(5 * x - 2 * y)}
                                                       : std::array<double, 2>{0.0, 0.0};
    s.particles.add(k, pos, vel, 1000.0 * spacing * spacing, 1000.0);
    s.gid.push_back(s.gid.size());
  };
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 40; ++j) add(Kind::Fluid, (i + 0.5) * spacing, (j + 0.5) * spacing);
  for (int i = -3; i < 83; ++i)
    for (int j = -3; j < 50; ++j)
      if (i < 0 || i >= 80 || j < 0) add(Kind::Wall, (i + 0.5) * spacing, (j + 0.5) * spacing);
  return s;
}

// The continuity rate of the first n_rows particles of a set (positions x, velocities v, masses,
// kinds, global ids over every particle the rows reach): rows within the support, in global-id
// order, evaluated by the library's continuity_rate.
std::vector<double> continuity_rates(const std::array<std::vector<double>, 2>& x, const std::array<std::vector<double>, 2>& v,
                                     const std::vector<double>& mass, const std::vector<Kind>& kind,
                                     const std::vector<std::uint64_t>& gid, std::size_t n_rows, const Domain<2>& domain) {
  PairList rows = test::serial_pairs<2>({x[0].data(), x[1].data()}, kind.data(), gid.size(), domain, support);
  order_rows_by_gid(rows, gid);
  Particles<2> carrier;  // continuity_rate reads the masses through the workspace's particles
  carrier.mass = mass;
  Workspace<2> w;
  w.particles = &carrier;
  w.domain = &domain;
  w.v = v;
  std::vector<double> out(n_rows);
  std::array<std::vector<double>, 2> dx;
  std::vector<double> F;
  for (std::size_t i = 0; i < n_rows; ++i) {
    const std::uint32_t o = rows.offset[i], n = rows.offset[i + 1] - o;
    for (auto& c : dx) c.resize(n);
    F.resize(n);
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::uint32_t j = rows.j[o + k];
      double r2 = 0.0;
      for (int d = 0; d < 2; ++d) {
        dx[d][k] = domain.min_image(d, x[d][i] - x[d][j]);
        r2 += dx[d][k] * dx[d][k];
      }
      const double r = std::sqrt(r2);
      double wk = 0.0, dw = 0.0;
      WendlandC2Kernel<2>::eval(r, h, wk, dw);
      F[k] = dw / r;
    }
    PairRow<2> row;
    row.n = n;
    row.j = rows.j.data() + o;
    row.dx = {dx[0].data(), dx[1].data()};
    row.F = F.data();
    out[i] = continuity_rate(w, i, row);
  }
  return out;
}

template <class T>
void append(std::vector<T>& a, const std::vector<T>& b) {
  a.insert(a.end(), b.begin(), b.end());
}

}  // namespace

TEST_CASE("gid-ordered rows: a distributed continuity rate equals the serial one bit for bit", "[parallel][continuity]") {
  const Communicator comm;
  const auto s = column_in_tank();
  const std::size_t n = s.gid.size();
  const std::vector<double> serial = continuity_rates(s.particles.x, s.particles.v, s.particles.mass, s.particles.kind, s.gid, n, s.domain);

  Particles<2> p;
  std::vector<std::uint64_t> gid;
  test::take_share(s, comm, p, gid);
  RcbPartitioner<2> rcb(comm, 1.05);
  Halo<2> halo;
  auto plan = [&] {
    halo.plan(comm, s.domain, gather_owned_bounds<2>(comm, test::positions(p), p.size()), test::positions(p), p.size(), support + skin);
  };
  // First by count, then by pair count: each particle's row length (+1) on owned + halo.
  std::vector<double> w(gid.size(), 1.0);
  migrate(comm, p, gid, rcb.partition(test::positions(p), w.data(), gid.data(), gid.size()).destination);
  plan();
  std::array<std::vector<double>, 2> x = p.x;
  for (int d = 0; d < 2; ++d) append(x[d], halo.exchange(comm, p.x[d]));
  std::vector<Kind> kind = p.kind;
  append(kind, halo.exchange(comm, p.kind));
  const PairList rows = test::serial_pairs<2>({x[0].data(), x[1].data()}, kind.data(), kind.size(), s.domain, support);
  w.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) w[i] = 1.0 + rows.offset[i + 1] - rows.offset[i];
  migrate(comm, p, gid, rcb.partition(test::positions(p), w.data(), gid.data(), gid.size()).destination, {&w});
  // Balanced within the tolerance plus one particle's weight (a cut cannot split a particle).
  const double local = std::accumulate(w.begin(), w.end(), 0.0);
  const double heaviest = comm.max(w.empty() ? 0.0 : *std::max_element(w.begin(), w.end()));
  CHECK(load_imbalance(comm, local) <= 1.05 + heaviest * comm.size() / comm.sum(local));

  // The evaluation: positions at the plan, the fields the pass reads just before it.
  plan();
  std::array<std::vector<double>, 2> xs = p.x, vs = p.v;
  for (int d = 0; d < 2; ++d) {
    append(xs[d], halo.exchange(comm, p.x[d]));
    append(vs[d], halo.exchange(comm, p.v[d]));
  }
  std::vector<double> mass = p.mass;
  append(mass, halo.exchange(comm, p.mass));
  std::vector<Kind> kinds = p.kind;
  append(kinds, halo.exchange(comm, p.kind));
  std::vector<std::uint64_t> ids = gid;
  append(ids, halo.exchange(comm, gid));
  const std::vector<double> mine = continuity_rates(xs, vs, mass, kinds, ids, p.size(), s.domain);

  // Every rate, gathered by global id, is the serial one to the bit.
  const std::vector<std::uint64_t> all_ids = comm.all_gather_v(gid);
  const std::vector<double> all_rates = comm.all_gather_v(mine);
  REQUIRE(all_ids.size() == n);
  std::size_t differ = 0, nonzero = 0;
  for (std::size_t k = 0; k < n; ++k) {
    differ += std::memcmp(&all_rates[k], &serial[all_ids[k]], sizeof(double)) != 0;
    nonzero += serial[all_ids[k]] != 0.0;
  }
  CHECK(differ == 0);
  CHECK(nonzero > n / 2);  // the rates are not trivially zero
}
