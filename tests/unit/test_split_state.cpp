// A state from two sources (rhs/split_state.hpp, SphSystem::rhs_split): on a tank with dynamic
// walls (wall densities in the state) and random velocities and densities, some fluid rows and
// walls owned and the rest handed over as shuffled rows of a buffer, the owned rows' rates equal
// the whole state's evaluation to the bit, nothing past the owned rates is written, and the CFL
// extremes are the owned rows'.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "probe_tank.hpp"
#include "sphmol/rhs/assemble.hpp"

using namespace sphmol;
using namespace probe_tank;

namespace {

std::unique_ptr<SphSystem<2>> make_tank(const Config& c) {
  Domain<2> dom;
  dom.lo = {-1, -1};
  dom.hi = {2, 2};
  return assemble_system<2>(c, tank(), dom, kDx);
}

struct SplitCase {
  SplitState<2> split;
  std::vector<double> owned;               // the owned rows, block-major (split.owned)
  std::vector<double> other;               // the other rows, `width` values each
  std::vector<std::uint32_t> fluid, wall;  // the owned fluid rows and wall-density rows
};

// Fluid rows and wall-density rows not divisible by 3 are owned, but for fluid row `not_owned`; the
// others go, in a shuffled order, to the buffer.
SplitCase split_of(const StateLayout<2>& L, const std::vector<double>& y, std::size_t not_owned = 0) {
  SplitCase s;
  const std::size_t n = L.n, nw = L.n_wall_density, width = 2 * 2 + L.extra_blocks();
  std::vector<std::uint32_t> rest_fluid, rest_wall;
  for (std::uint32_t i = 0; i < n; ++i) (i % 3 && i != not_owned ? s.fluid : rest_fluid).push_back(i);
  for (std::uint32_t k = 0; k < nw; ++k) (k % 3 ? s.wall : rest_wall).push_back(k);
  std::mt19937 rng(5);
  std::shuffle(rest_fluid.begin(), rest_fluid.end(), rng);
  std::shuffle(rest_wall.begin(), rest_wall.end(), rng);
  s.split.owned = L;
  s.split.owned.n = s.fluid.size();
  s.split.owned.n_wall_density = s.wall.size();
  s.split.width = width;
  const StateLayout<2>& O = s.split.owned;
  s.split.fluid_source.resize(n);
  s.split.wall_source.resize(nw);
  s.owned.assign(O.size(), 0.0);
  for (std::size_t o = 0; o < s.fluid.size(); ++o) {
    s.split.fluid_source[s.fluid[o]] = static_cast<std::uint32_t>(o);
    for (std::size_t b = 0; b < width; ++b) s.owned[b * O.n + o] = y[b * n + s.fluid[o]];
  }
  for (std::size_t o = 0; o < s.wall.size(); ++o) {
    s.split.wall_source[s.wall[o]] = static_cast<std::uint32_t>(o);
    s.owned[O.wall_density() + o] = y[L.wall_density() + s.wall[o]];
  }
  // The buffer: the other fluid rows, then the other walls (a wall's density in the first entry).
  for (std::size_t q = 0; q < rest_fluid.size(); ++q) {
    s.split.fluid_source[rest_fluid[q]] = static_cast<std::uint32_t>(O.n + q);
    for (std::size_t b = 0; b < width; ++b) s.other.push_back(y[b * n + rest_fluid[q]]);
  }
  for (std::size_t q = 0; q < rest_wall.size(); ++q) {
    s.split.wall_source[rest_wall[q]] = static_cast<std::uint32_t>(O.n_wall_density + rest_fluid.size() + q);
    s.other.push_back(y[L.wall_density() + rest_wall[q]]);
    s.other.insert(s.other.end(), width - 1, std::numeric_limits<double>::quiet_NaN());
  }
  s.split.fluid_rate_row = s.fluid;
  s.split.wall_rate_row = s.wall;
  return s;
}

// The whole system, the one evaluated from a split state (both the tank with dynamic walls), and a
// state with random velocities.
struct Systems {
  std::unique_ptr<SphSystem<2>> whole, local;
  StateLayout<2> L;
  std::vector<double> y;
};

Systems make_systems(unsigned seed) {
  Config c = tank_config();
  c.discretization.wall_pressure = "dynamic";
  Systems p{make_tank(c), make_tank(c), {}, {}};
  p.L = p.whole->layout();
  p.y = p.whole->initial_state();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (std::size_t k = p.L.velocities_begin(); k < p.L.velocities_end(); ++k) p.y[k] = u(rng);
  return p;
}

}  // namespace

TEST_CASE("split state: the owned rows' rates from two sources equal the whole state's to the bit", "[split_state]") {
  Systems p = make_systems(17);
  auto& whole = p.whole;
  auto& local = p.local;
  const StateLayout<2> L = p.L;
  std::vector<double>& y = p.y;
  REQUIRE(L.has_density);
  REQUIRE(L.n_wall_density > 0);
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (std::size_t i = 0; i < L.n; ++i) y[L.density() + i] *= 1.0 + 0.01 * u(rng);
  for (std::size_t k = 0; k < L.n_wall_density; ++k) y[L.wall_density() + k] *= 1.0 + 0.01 * u(rng);
  std::vector<double> f(L.size());
  whole->rhs(0.0, y.data(), f.data());

  // The largest acceleration is not an owned row's: the owned rows' extremes are their own.
  std::size_t fastest = 0;
  double fastest_a2 = -1.0;
  for (std::size_t i = 0; i < L.n; ++i) {
    const double a2 = f[L.velocity(0) + i] * f[L.velocity(0) + i] + f[L.velocity(1) + i] * f[L.velocity(1) + i];
    if (a2 > fastest_a2) {
      fastest = i;
      fastest_a2 = a2;
    }
  }
  SplitCase s = split_of(L, y, fastest);
  const StateLayout<2> O = s.split.owned;
  local->set_split_state(s.split);
  // Sentinels past the owned rates: the other rows' rates are not written anywhere.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> ydot(O.size() + 64, nan);
  // Two evaluations: the second reads the sources again (the pair list kept).
  for (int pass = 0; pass < 2; ++pass) {
    local->rhs_split(0.0, s.owned.data(), s.other.data(), ydot.data());
    for (std::size_t b = 0; b < 2 * 2 + L.extra_blocks(); ++b)
      for (std::size_t o = 0; o < O.n; ++o) REQUIRE(ydot[b * O.n + o] == f[b * L.n + s.fluid[o]]);
    for (std::size_t o = 0; o < O.n_wall_density; ++o) REQUIRE(ydot[O.wall_density() + o] == f[L.wall_density() + s.wall[o]]);
    for (std::size_t k = O.size(); k < ydot.size(); ++k) REQUIRE(std::isnan(ydot[k]));
  }
  REQUIRE(local->density() == whole->density());

  // The CFL extremes over the owned fluid rows, as SphSystem::rhs takes them over all rows.
  double amax2 = 0.0, acoustic = std::numeric_limits<double>::infinity(), hmin = whole->smoothing_length();
  const auto& v = whole->velocities();
  for (const std::uint32_t i : s.fluid) {
    double v2 = 0.0, a2 = 0.0;
    for (int d = 0; d < 2; ++d) {
      v2 += v[d][i] * v[d][i];
      a2 += f[L.velocity(d) + i] * f[L.velocity(d) + i];
    }
    amax2 = std::max(amax2, a2);
    const double speed = std::max(whole->cfl_limits().sound_speed, whole->sound_speed()[i]) + std::sqrt(v2);
    if (speed > 0.0) acoustic = std::min(acoustic, whole->smoothing_lengths()[i] / speed);
    hmin = std::min(hmin, whole->smoothing_lengths()[i]);
  }
  REQUIRE(local->cfl_extremes().amax2 == amax2);
  REQUIRE(local->cfl_extremes().acoustic == acoustic);
  REQUIRE(local->cfl_extremes().hmin == hmin);
  // The whole evaluation's extremes take every row.
  REQUIRE(whole->cfl_extremes().amax2 == fastest_a2);
  REQUIRE(fastest_a2 > amax2);

  // rhs() still takes a whole state after a split evaluation.
  std::vector<double> f2(L.size());
  local->rhs(0.0, y.data(), f2.data());
  REQUIRE(f2 == f);
}

TEST_CASE("split state: the explicit part and the viscous operator from two sources", "[split_state][imex]") {
  Systems p = make_systems(23);
  auto& whole = p.whole;
  auto& local = p.local;
  const StateLayout<2> L = p.L;
  const std::vector<double>& y = p.y;
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  std::vector<double> fe(L.size());
  ViscousOperator op_whole, op_local;
  whole->rhs_explicit(0.0, y.data(), fe.data(), op_whole);
  SplitCase s = split_of(L, y);
  local->set_split_state(s.split);
  std::vector<double> ydot(s.split.owned.size());
  local->rhs_explicit_split(0.0, s.owned.data(), s.other.data(), ydot.data(), op_local);
  const StateLayout<2> O = s.split.owned;
  for (std::size_t b = 0; b < 2 * 2 + L.extra_blocks(); ++b)
    for (std::size_t o = 0; o < O.n; ++o) REQUIRE(ydot[b * O.n + o] == fe[b * L.n + s.fluid[o]]);
  // The operator's rows are the system's (all rows, in the system's order): the same as the whole's.
  REQUIRE(op_local.size() == op_whole.size());
  REQUIRE(op_whole.size() > 0);
  std::vector<double> x(op_whole.size()), a(x.size()), b(x.size());
  for (auto& e : x) e = u(rng);
  op_whole.apply(x.data(), a.data());
  op_local.apply(x.data(), b.data());
  REQUIRE(a == b);
}

TEST_CASE("split state: a split that does not fit the system is refused", "[split_state]") {
  Systems p = make_systems(31);
  auto& sys = p.local;
  const StateLayout<2> L = p.L;
  std::vector<double> y = p.y, ydot(L.size());
  REQUIRE_THROWS_AS(sys->rhs_split(0.0, y.data(), nullptr, ydot.data()), std::logic_error);
  SplitCase s = split_of(L, y);
  s.split.fluid_source.pop_back();
  REQUIRE_THROWS_AS(sys->set_split_state(s.split), std::invalid_argument);
  s = split_of(L, y);
  sys->set_split_state(s.split);
  REQUIRE_THROWS_AS(sys->set_reorder(true), std::logic_error);
}
