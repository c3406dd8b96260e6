// The implicit-explicit split of the RHS (time/imex_system.hpp, time/viscous_operator.hpp) on a small
// tank with walls and random velocities: f_E + L v + b equals the full f to round-off for every
// wall model, pair-pass mode and ordering the IMEX integrators accept; L is the exact Jacobian of f
// in the velocities at fixed positions (finite differences of the full RHS); its diagonal is L
// applied to unit vectors; the explicit part's CFL limit has no viscous limit.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "probe_tank.hpp"
#include "sphmol/rhs/assemble.hpp"

using namespace sphmol;
using namespace probe_tank;

namespace {

struct Split {
  std::unique_ptr<SphSystem<2>> sys;
  std::vector<double> y, f, fe;
  ViscousOperator op;
  std::size_t vb = 0, nv = 0;
};

Split make_split(const Config& c) {
  Split s;
  Domain<2> dom;
  dom.lo = {-1, -1};
  dom.hi = {2, 2};
  Particles<2> P = tank();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  for (std::size_t i = 0; i < P.n_fluid; ++i)
    for (int d = 0; d < 2; ++d) P.v[d][i] = u(rng);
  // A moving floor: wall velocities enter b.
  for (std::size_t i = P.n_fluid; i < P.size(); ++i)
    if (P.body[i] == 0) P.v[0][i] = 0.02;
  s.sys = assemble_system<2>(c, std::move(P), dom, kDx);
  s.y = s.sys->initial_state();
  s.f.resize(s.y.size());
  s.fe.resize(s.y.size());
  s.vb = s.sys->velocities_begin();
  s.nv = s.sys->velocities_end() - s.vb;
  s.sys->rhs(0.0, s.y.data(), s.f.data());
  s.sys->rhs_explicit(0.0, s.y.data(), s.fe.data(), s.op);
  return s;
}

double max_abs(const std::vector<double>& v, std::size_t lo, std::size_t hi) {
  double m = 0.0;
  for (std::size_t k = lo; k < hi; ++k) m = std::max(m, std::abs(v[k]));
  return m;
}

}  // namespace

TEST_CASE("IMEX split: f_E + L v + b equals f to round-off", "[imex]") {
  Config c = tank_config();
  c.fluid.kinematic_viscosity = 1e-2;  // the viscous sum dominates the velocity rates
  std::string wall_model = GENERATE(std::string("prescribed"), std::string("morris"));
  std::string passes = GENERATE(std::string("stored"), std::string("fused"));
  bool reorder = GENERATE(false, true);
  std::string correction = GENERATE(std::string("none"), std::string("moment"), std::string("moment_symmetric"));
  c.discretization.wall_model = wall_model;
  c.discretization.pair_passes = passes;
  // The extrapolated wall pressure reads the stored pair list; fused passes need rest pressures.
  if (passes == "fused") c.discretization.wall_pressure = "rest";
  c.discretization.reorder = reorder;
  c.discretization.laplacian_correction = correction;
  INFO(wall_model << ", " << passes << ", reorder " << reorder << ", laplacian_correction " << correction);
  Split s = make_split(c);
  REQUIRE(s.op.size() == s.nv);
  REQUIRE(s.sys->implicit_terms().size() == (wall_model == "morris" ? 2u : 1u));
  std::vector<double> fi(s.nv);
  s.op.apply_affine(s.y.data() + s.vb, fi.data());
  const double scale = max_abs(s.f, s.vb, s.vb + s.nv);
  REQUIRE(scale > 0.0);
  // The viscous part is not small: the split is not trivially f_E = f.
  CHECK(max_abs(fi, 0, s.nv) > 0.01 * scale);
  double worst = 0.0;
  for (std::size_t k = 0; k < s.nv; ++k) worst = std::max(worst, std::abs(s.fe[s.vb + k] + fi[k] - s.f[s.vb + k]));
  CHECK(worst < 1e-12 * scale);
  // Every other rate (positions, with XSPH off: the velocities) is the explicit part's alone, bit for bit.
  for (std::size_t k = 0; k < s.vb; ++k) REQUIRE(s.fe[k] == s.f[k]);
  for (std::size_t k = s.vb + s.nv; k < s.y.size(); ++k) REQUIRE(s.fe[k] == s.f[k]);
}

TEST_CASE("IMEX split: L is the Jacobian of f in the velocities (finite differences)", "[imex]") {
  Config c = tank_config();
  c.discretization.wall_model = "morris";
  Split s = make_split(c);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> w(s.nv), Lw(s.nv), y2 = s.y, f2(s.y.size());
  for (auto& x : w) x = u(rng);
  const double eps = 1e-4;  // f is affine in v at fixed positions: any eps, up to round-off
  for (std::size_t k = 0; k < s.nv; ++k) y2[s.vb + k] += eps * w[k];
  s.sys->rhs(0.0, y2.data(), f2.data());
  s.op.apply(w.data(), Lw.data());
  const double scale = max_abs(Lw, 0, s.nv);
  REQUIRE(scale > 0.0);
  double worst = 0.0;
  for (std::size_t k = 0; k < s.nv; ++k) worst = std::max(worst, std::abs((f2[s.vb + k] - s.f[s.vb + k]) / eps - Lw[k]));
  CHECK(worst < 1e-6 * scale);
}

TEST_CASE("IMEX split: the Jacobi diagonal is L applied to unit vectors", "[imex]") {
  Config c = tank_config();
  c.discretization.wall_model = "morris";
  c.discretization.reorder = true;  // the diagonal is in state order, the rows in workspace order
  Split s = make_split(c);
  const std::size_t n = s.op.rows();
  std::vector<double> e(s.nv, 0.0), Le(s.nv);
  for (std::size_t i : {std::size_t{0}, n / 3, n / 2, n - 1}) {
    for (int d = 0; d < 2; ++d) {
      std::fill(e.begin(), e.end(), 0.0);
      e[d * n + i] = 1.0;
      s.op.apply(e.data(), Le.data());
      INFO("particle " << i << ", component " << d);
      CHECK(Le[d * n + i] == Approx(s.op.diagonal()[i]).epsilon(1e-14));
      CHECK(s.op.diagonal()[i] < 0.0);
      // Off-diagonal entries of the column: each neighbour's coefficient, of the opposite sign.
      double column = 0.0;
      for (std::size_t k = 0; k < s.nv; ++k)
        if (k != d * n + i) column += Le[k];
      CHECK(column > 0.0);
    }
  }
}

TEST_CASE("IMEX split: with moment_symmetric the operator keeps m_i L_ij = m_j L_ji, with moment it does not", "[imex]") {
  // m_i L_ij is the momentum particle i receives per unit velocity of j: symmetric for equal and
  // opposite pair forces, and the symmetry conjugate gradients rely on (equal masses: L itself).
  const std::string correction = GENERATE(std::string("moment_symmetric"), std::string("moment"));
  Config c = tank_config();
  c.discretization.laplacian_correction = correction;
  c.discretization.reorder = true;
  INFO("laplacian_correction " << correction);
  Split s = make_split(c);
  const std::size_t n = s.op.rows();
  const Particles<2> P = tank();
  std::vector<double> e(s.nv, 0.0), Li(s.nv), Lk(s.nv);
  double worst = 0.0, scale = 0.0;
  for (std::size_t i : {std::size_t{0}, n / 3, n / 2, n - 1}) {
    std::fill(e.begin(), e.end(), 0.0);
    e[i] = 1.0;
    s.op.apply(e.data(), Li.data());  // column i: L_ki
    for (std::size_t k = 0; k < n; ++k) {
      if (k == i || Li[k] == 0.0) continue;
      std::fill(e.begin(), e.end(), 0.0);
      e[k] = 1.0;
      s.op.apply(e.data(), Lk.data());  // column k: L_ik at row i
      worst = std::max(worst, std::abs(P.mass[k] * Li[k] - P.mass[i] * Lk[i]));
      scale = std::max(scale, std::abs(P.mass[i] * Lk[i]));
    }
  }
  REQUIRE(scale > 0.0);
  if (correction == "moment_symmetric") CHECK(worst < 1e-13 * scale);
  else CHECK(worst > 1e-6 * scale);
}

TEST_CASE("IMEX split: the explicit part's CFL limit has no viscous limit", "[imex]") {
  Config c = tank_config();
  c.fluid.kinematic_viscosity = 100.0;  // viscous limit 0.125 h^2 / nu far below the acoustic one
  c.discretization.wall_model = "morris";
  Split s = make_split(c);  // the last evaluation is rhs_explicit
  const double explicit_step = s.sys->stable_step();
  s.sys->rhs(0.0, s.y.data(), s.f.data());
  const double full_step = s.sys->stable_step();
  const double h = c.discretization.smoothing_ratio * kDx;
  CHECK(full_step == Approx(0.125 * h * h / 100.0));
  CHECK(explicit_step > 10.0 * full_step);
}
