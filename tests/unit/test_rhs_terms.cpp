// RHS terms on small particle sets: exactness on lattices, pairwise antisymmetry (momentum), and the
// Morris wall model's exactness for a linear shear profile at the wall.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "sphmol/boundary/morris_wall_velocity.hpp"
#include "sphmol/kernels/cubic_spline.hpp"
#include "sphmol/physics/body_force.hpp"
#include "sphmol/physics/bulk_viscosity.hpp"
#include "sphmol/physics/eos_linear.hpp"
#include "sphmol/physics/morris_moment.hpp"
#include "sphmol/physics/morris_viscosity.hpp"
#include "sphmol/physics/pressure_gradient.hpp"
#include "sphmol/physics/strain_rate.hpp"
#include "sphmol/physics/strain_rate_viscosity.hpp"
#include "sphmol/physics/summation_density.hpp"
#include "sphmol/physics/transport_velocity.hpp"
#include "sphmol/physics/xsph.hpp"
#include "sphmol/rhs/sph_system.hpp"
#include "sphmol/scenes/lattice_mass.hpp"

#include "workspace_pairs.hpp"

using namespace sphmol;

namespace {

// A 2D particle set with its workspace ready for terms: pairs, kernel values, rest density.
struct Fixture {
  Particles<2> P;
  Domain<2> dom;
  Workspace<2> w;
  PairList verlet;
  std::array<std::vector<double>, 2> dxdt, dvdt;
  double dx = 0.1, h = 0.13, rho0 = 1000.0;

  // n x n fluid lattice in [0,1)^2 (periodic) or [0, n dx) (open), optional wall rows below y = 0.
  Fixture(int n, bool periodic, int wall_layers = 0, double jitter = 0.0) {
    dx = 1.0 / n;
    h = 1.3 * dx;
    const double m = lattice_particle_mass<2>("cubic_spline", rho0, dx, h);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-jitter * dx, jitter * dx);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) P.add(Kind::Fluid, {(i + 0.5) * dx + u(rng), (j + 0.5) * dx + u(rng)}, {0, 0}, m, rho0);
    for (int k = 0; k < wall_layers; ++k)
      for (int i = 0; i < n; ++i) P.add(Kind::Wall, {(i + 0.5) * dx, -(k + 0.5) * dx}, {0, 0}, m, rho0, {0.0, 1.0}, (k + 0.5) * dx);
    dom.lo = {0.0, -wall_layers * dx};
    dom.hi = {1.0, 1.0};
    dom.periodic = {periodic, periodic && wall_layers == 0};
    load_workspace(w, P, dom, h);
    w.W0 = CubicSpline<2>::W(0.0, h);
    for (int d = 0; d < 2; ++d) {
      dxdt[d].assign(P.n_fluid, 0.0);
      dvdt[d].assign(P.n_fluid, 0.0);
      w.dxdt[d] = dxdt[d].data();
      w.dvdt[d] = dvdt[d].data();
    }
    for (auto& s : w.strain) s.assign(w.n, 0.0);
  }
  void pairs() {
    // With a skin: the kernel pass must drop the extra pairs.
    build_workspace_pairs<2, CubicSpline<2>>(w, P, dom, 2.0 * h * 1.2, verlet);
  }
  std::size_t centre() const {  // fluid particle nearest the middle of the lattice
    std::size_t best = 0;
    double bd = 1e9;
    for (std::size_t i = 0; i < P.n_fluid; ++i) {
      const double d = std::hypot(P.x[0][i] - 0.5, P.x[1][i] - 0.5);
      if (d < bd) bd = d, best = i;
    }
    return best;
  }
};

// Pair forces cancel: total momentum rate sum_i m_i dv_i/dt vanishes relative to sum_i m_i |dv_i/dt|.
void check_momentum_conserved(const Fixture& f) {
  double px = 0, py = 0, scale = 0;
  for (std::size_t i = 0; i < f.P.n_fluid; ++i) {
    px += f.P.mass[i] * f.dvdt[0][i];
    py += f.P.mass[i] * f.dvdt[1][i];
    scale += f.P.mass[i] * std::hypot(f.dvdt[0][i], f.dvdt[1][i]);
  }
  REQUIRE(scale > 0);
  CHECK(std::abs(px) < 1e-12 * scale);
  CHECK(std::abs(py) < 1e-12 * scale);
}

}  // namespace

TEST_CASE("kernel pass keeps exactly the pairs inside the support", "[rhs]") {
  Fixture f(12, true);
  f.pairs();
  std::size_t inside = 0;
  for (std::size_t i = 0; i < f.verlet.rows(); ++i)
    for (auto q = f.verlet.offset[i]; q < f.verlet.offset[i + 1]; ++q) {
      const std::size_t j = f.verlet.j[q];
      const double r = std::hypot(f.dom.min_image(0, f.w.x[0][i] - f.w.x[0][j]), f.dom.min_image(1, f.w.x[1][i] - f.w.x[1][j]));
      if (r < 2.0 * f.h) ++inside;
    }
  CHECK(f.w.pairs.pairs() == inside);
  CHECK(f.w.pairs.pairs() < f.verlet.pairs());
  for (std::size_t k = 0; k < f.w.pairs.pairs(); ++k) {
    const double r = std::hypot(f.w.dx[0][k], f.w.dx[1][k]);
    CHECK(f.w.W[k] == Approx(CubicSpline<2>::W(r, f.h)).epsilon(1e-13));
    CHECK(f.w.F[k] * r == Approx(CubicSpline<2>::dWdr(r, f.h)).epsilon(1e-12).margin(1e-9));
  }
}

TEST_CASE("summation density returns the rest density on the lattice it was calibrated for", "[rhs]") {
  Fixture f(16, true);
  f.pairs();
  SummationDensity<2>().apply(f.w);
  for (std::size_t i = 0; i < f.P.n_fluid; ++i) CHECK(f.w.rho[i] == Approx(f.rho0).epsilon(1e-12));
}

TEST_CASE("pressure gradient: zero for uniform pressure, -grad p / rho for a linear one", "[rhs]") {
  Fixture f(20, false);
  f.pairs();
  const std::size_t c = f.centre();
  LinearEos<2>(2.0, f.rho0, false).apply(f.w);  // uniform density -> uniform p
  PressureGradient117<2>().apply(f.w);
  CHECK(std::abs(f.dvdt[0][c]) < 1e-12 * 4.0 / f.dx);
  CHECK(std::abs(f.dvdt[1][c]) < 1e-12 * 4.0 / f.dx);
  const double G = 3.0;
  for (std::size_t i = 0; i < f.w.n; ++i) f.w.p[i] = 10.0 + G * f.w.x[1][i];
  f.dvdt[0].assign(f.P.n_fluid, 0.0);
  f.dvdt[1].assign(f.P.n_fluid, 0.0);
  PressureGradient117<2>().apply(f.w);
  CHECK(f.dvdt[1][c] == Approx(-G / f.rho0).epsilon(2e-2));
  CHECK(std::abs(f.dvdt[0][c]) < 1e-12);
}

TEST_CASE("Morris viscosity approximates nu * laplacian(u) for a quadratic profile", "[rhs]") {
  Fixture f(20, false);
  f.pairs();
  const double nu = 1e-3, mu = nu * f.rho0;
  for (std::size_t i = 0; i < f.w.n; ++i) f.w.v[0][i] = f.w.x[1][i] * f.w.x[1][i];  // u = y^2, lap u = 2
  MorrisViscosity<2>(mu).apply(f.w);
  const std::size_t c = f.centre();
  CHECK(f.dvdt[0][c] == Approx(2.0 * nu).epsilon(2e-2));
  CHECK(std::abs(f.dvdt[1][c]) < 1e-12);
}

TEST_CASE("Morris viscosity normalised by its second moment is exact for a quadratic profile", "[rhs]") {
  Fixture f(20, false);
  f.pairs();
  const double nu = 1e-3, mu = nu * f.rho0;
  for (std::size_t i = 0; i < f.w.n; ++i) f.w.v[0][i] = f.w.x[1][i] * f.w.x[1][i];  // u = y^2, lap u = 2
  MorrisViscosity<2, LaplacianCorrection::moment>(mu).apply(f.w);
  const std::size_t c = f.centre();
  CHECK(f.dvdt[0][c] == Approx(2.0 * nu).epsilon(1e-10));
  CHECK(std::abs(f.dvdt[1][c]) < 1e-12);
}

TEST_CASE("Morris viscosity with the pair-symmetric moment is exact for a quadratic profile", "[rhs]") {
  Fixture f(20, false);
  f.pairs();
  const double nu = 1e-3, mu = nu * f.rho0;
  for (std::size_t i = 0; i < f.w.n; ++i) f.w.v[0][i] = f.w.x[1][i] * f.w.x[1][i];  // u = y^2, lap u = 2
  auto moment = std::make_shared<MorrisMomentField>();
  MorrisMoment<2>(moment).apply(f.w);
  const std::size_t c = f.centre();
  // The lattice's moment is not 1 (else the test would not tell the corrected sum from the plain one).
  CHECK(std::abs((*moment)[c] - 1.0) > 1e-5);
  MorrisViscosity<2, LaplacianCorrection::moment_symmetric>(mu, moment).apply(f.w);
  CHECK(f.dvdt[0][c] == Approx(2.0 * nu).epsilon(1e-10));
  CHECK(std::abs(f.dvdt[1][c]) < 1e-12);
}

namespace {
// Random velocities in [-1, 1] on the fixture's first `moving` particles (all by default; the rest at
// rest), its pairs and its summed density: a disordered state on which pairwise antisymmetry, not
// lattice symmetry, has to cancel the forces.
void random_flow(Fixture& f, unsigned seed = 3, std::size_t moving = std::numeric_limits<std::size_t>::max()) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < std::min(moving, f.w.n); ++i) {
    f.w.v[0][i] = u(rng);
    f.w.v[1][i] = u(rng);
  }
  f.pairs();
  SummationDensity<2>().apply(f.w);
}
}  // namespace

TEST_CASE("Morris viscosity with the pair-symmetric moment conserves momentum on a disordered set, the row moment does not", "[rhs]") {
  Fixture f(14, true, 0, 0.2);
  random_flow(f);
  auto moment = std::make_shared<MorrisMomentField>();
  MorrisMoment<2>(moment).apply(f.w);
  MorrisViscosity<2, LaplacianCorrection::moment_symmetric>(0.01, moment).apply(f.w);
  check_momentum_conserved(f);
  // The row normalisation on the same set: unequal moments, unequal pair forces.
  for (int d = 0; d < 2; ++d) f.dvdt[d].assign(f.P.n_fluid, 0.0);
  MorrisViscosity<2, LaplacianCorrection::moment>(0.01).apply(f.w);
  double px = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < f.P.n_fluid; ++i) {
    px += f.P.mass[i] * f.dvdt[0][i];
    scale += f.P.mass[i] * std::abs(f.dvdt[0][i]);
  }
  CHECK(std::abs(px) > 1e-6 * scale);
}

TEST_CASE("strain rate of a linear shear flow, in the interior and at wall particles", "[rhs]") {
  const double gamma = 0.7;
  Fixture f(16, true, 3);
  for (std::size_t i = 0; i < f.P.n_fluid; ++i) f.w.v[0][i] = gamma * f.w.x[1][i];  // walls at rest: u = 0 at y = 0
  f.pairs();
  SECTION("Morris wall velocities make the wall rows exact") {
    MorrisWallVelocity<2>(100.0, true).apply(f.w);
    StrainRate<2>().apply(f.w);
    for (std::size_t i = f.P.n_fluid; i < f.w.n; ++i) {
      bool has_fluid = f.w.pairs.offset[i + 1] > f.w.pairs.offset[i];
      if (!has_fluid) continue;
      CHECK(f.w.strain[1][i] == Approx(gamma).epsilon(1e-10));  // eps_xy
      CHECK(f.w.strain[0][i] == Approx(0.0).margin(1e-10));
    }
    // Fluid particles well inside: the plain sums are exact for a linear field up to the lattice
    // moment -sum V F dx dx^T, which is 1.011 for the cubic spline at h = 1.3 dx (measured).
    const std::size_t c = f.centre();
    CHECK(f.w.strain[1][c] == Approx(gamma).epsilon(2e-2));
  }
  SECTION("without the wall model the first fluid row sees a wrong gradient") {
    StrainRate<2>().apply(f.w);
    std::size_t first_row = 0;  // particle at y = dx/2
    CHECK(std::abs(f.w.strain[1][first_row] - gamma) > 0.05 * gamma);
  }
}

TEST_CASE("pressure and viscous pair forces conserve momentum on a disordered periodic set", "[rhs]") {
  Fixture f(14, true, 0, 0.2);
  random_flow(f);
  LinearEos<2>(1.5, f.rho0, false).apply(f.w);
  StrainRate<2>().apply(f.w);
  PressureGradient117<2>().apply(f.w);
  MorrisViscosity<2>(0.01).apply(f.w);
  StrainRateViscosity117<2>(0.01).apply(f.w);
  check_momentum_conserved(f);
}

TEST_CASE("XSPH leaves a uniform flow alone and body force adds g", "[rhs]") {
  Fixture f(12, true);
  for (std::size_t i = 0; i < f.w.n; ++i) f.w.v[0][i] = 0.3;
  f.pairs();
  SummationDensity<2>().apply(f.w);
  for (std::size_t i = 0; i < f.P.n_fluid; ++i) f.dxdt[0][i] = f.w.v[0][i];
  Xsph<2>(0.5).apply(f.w);
  BodyForce<2>({1.0, -9.81}).apply(f.w);
  for (std::size_t i = 0; i < f.P.n_fluid; ++i) {
    CHECK(f.dxdt[0][i] == Approx(0.3).epsilon(1e-14));
    CHECK(f.dvdt[1][i] == Approx(-9.81));
  }
}

// The transport-velocity shift, and the extra stress after it when `stress` (as the assembly chains them).
void transport_velocity(Workspace<2>& w, double pb, double tau, bool stress) {
  auto du = stress ? std::make_shared<TransportShiftField<2>>() : nullptr;
  TransportVelocityShift<2>(pb, tau, du).apply(w);
  if (stress) TransportVelocityStress<2>(du).apply(w);
}

TEST_CASE("transport velocity: nothing on a lattice, pushes displaced particles back, stress conserves momentum",
          "[rhs][transport_velocity]") {
  const double pb = 2.0e5, tau = 1e-4;
  SECTION("perfect periodic lattice: no shift, no extra stress") {
    Fixture f(12, true);
    for (std::size_t i = 0; i < f.w.n; ++i) f.w.v[0][i] = std::sin(2 * M_PI * f.w.x[1][i]);
    f.pairs();
    SummationDensity<2>().apply(f.w);
    transport_velocity(f.w, pb, tau, true);
    for (std::size_t i = 0; i < f.P.n_fluid; ++i)
      for (int d = 0; d < 2; ++d) {
        CHECK(std::abs(f.dxdt[d][i]) < 1e-12);
        CHECK(std::abs(f.dvdt[d][i]) < 1e-9);
      }
  }
  SECTION("jittered lattice: the shift points back towards the lattice sites, linear in tau p_b") {
    Fixture f(14, true, 0, 0.1);
    f.pairs();
    SummationDensity<2>().apply(f.w);
    transport_velocity(f.w, pb, tau, false);
    double along = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < f.P.n_fluid; ++i) {
      const int ix = static_cast<int>(i % 14), iy = static_cast<int>(i / 14);
      const double xi[2] = {f.P.x[0][i] - (ix + 0.5) * f.dx, f.P.x[1][i] - (iy + 0.5) * f.dx};
      for (int d = 0; d < 2; ++d) {
        along += f.dxdt[d][i] * xi[d];
        norm += f.dxdt[d][i] * f.dxdt[d][i];
      }
    }
    REQUIRE(norm > 0);
    CHECK(along < 0);  // back towards the sites, on balance
    const double first = f.dxdt[0][5];
    f.dxdt[0].assign(f.P.n_fluid, 0.0);
    f.dxdt[1].assign(f.P.n_fluid, 0.0);
    transport_velocity(f.w, 2 * pb, 3 * tau, false);
    CHECK(f.dxdt[0][5] == Approx(6 * first).epsilon(1e-12));
  }
  SECTION("extra stress: pairwise, so total momentum is conserved on a disordered set") {
    Fixture f(14, true, 0, 0.2);
    random_flow(f, 5);
    transport_velocity(f.w, pb, tau, true);
    check_momentum_conserved(f);
  }
}

namespace {
// The bulk viscosity's two passes on the fixture: divergences, then the viscous pressure's forces.
std::shared_ptr<VelocityDivergenceField> apply_bulk_viscosity(Fixture& f, double zeta) {
  auto div = std::make_shared<VelocityDivergenceField>();
  VelocityDivergence<2>(div).apply(f.w);
  BulkViscosity<2>(zeta, div).apply(f.w);
  return div;
}

// At uniform density the power of the bulk viscosity over the fluid, sum_i m_i v_i . dv_i/dt, is
// exactly -zeta sum_i m_i div_i^2 (walls at rest): the force is the divergence's adjoint.
std::shared_ptr<VelocityDivergenceField> check_exact_dissipation(Fixture& f, double zeta) {
  for (auto& r : f.w.rho) r = f.rho0;
  const auto div = apply_bulk_viscosity(f, zeta);
  double power = 0.0, expected = 0.0;
  for (std::size_t i = 0; i < f.P.n_fluid; ++i) {
    power += f.P.mass[i] * (f.w.v[0][i] * f.dvdt[0][i] + f.w.v[1][i] * f.dvdt[1][i]);
    expected -= zeta * f.P.mass[i] * (*div)[i] * (*div)[i];
  }
  REQUIRE(expected < 0.0);
  CHECK(power == Approx(expected).epsilon(1e-10));
  return div;
}
}  // namespace

TEST_CASE("bulk viscosity: nothing on a divergence-free shear wave, zeta k^2 damping of a sound wave", "[rhs]") {
  const double zeta = 0.3, k = 2.0 * M_PI;
  SECTION("a shear wave u = sin(k y) has no divergence and gets no force") {
    Fixture f(20, true);
    for (std::size_t i = 0; i < f.w.n; ++i) f.w.v[0][i] = std::sin(k * f.w.x[1][i]);
    f.pairs();
    const auto div = apply_bulk_viscosity(f, zeta);
    for (std::size_t i = 0; i < f.P.n_fluid; ++i) {
      CHECK(std::abs((*div)[i]) < 1e-10);
      CHECK(std::abs(f.dvdt[0][i]) < 1e-9);
      CHECK(std::abs(f.dvdt[1][i]) < 1e-9);
    }
  }
  SECTION("a sound wave u = sin(k x): div = k cos(k x), dv/dt = zeta d(div)/dx = -zeta k^2 sin(k x)") {
    Fixture f(40, true);
    for (std::size_t i = 0; i < f.w.n; ++i) f.w.v[0][i] = std::sin(k * f.w.x[0][i]);
    f.pairs();
    const auto div = apply_bulk_viscosity(f, zeta);
    double worst_div = 0.0, worst_a = 0.0;
    for (std::size_t i = 0; i < f.P.n_fluid; ++i) {
      const double x = f.w.x[0][i];
      worst_div = std::max(worst_div, std::abs((*div)[i] - k * std::cos(k * x)));
      worst_a = std::max(worst_a, std::abs(f.dvdt[0][i] + zeta * k * k * std::sin(k * x)));
      CHECK(std::abs(f.dvdt[1][i]) < 1e-9);
    }
    // The kernel's smoothing of a wave 40 spacings long (k h = 0.2): a few per cent.
    CHECK(worst_div < 0.03 * k);
    CHECK(worst_a < 0.05 * zeta * k * k);
  }
}

TEST_CASE("bulk viscosity conserves momentum and dissipates exactly -zeta sum m div^2 at uniform density", "[rhs]") {
  Fixture f(14, true, 0, 0.2);
  random_flow(f);
  const double zeta = 0.05;
  SECTION("momentum on a disordered set with its summed density") {
    apply_bulk_viscosity(f, zeta);
    check_momentum_conserved(f);
  }
  SECTION("kinetic energy at uniform density") { check_exact_dissipation(f, zeta); }
}

TEST_CASE("bulk viscosity at walls at rest: the dissipation is exactly -zeta sum m div^2, walls in the divergence", "[rhs]") {
  // Walls enter the divergence with their velocity and have no viscous pressure of their own, so the
  // force is the adjoint of the divergence and the term only dissipates. (The mirror rule of the
  // extrapolated wall pressure, a wall taking the fluid particle's viscous pressure, counts the wall
  // pairs twice and fails this.)
  Fixture f(14, true, 3, 0.2);
  random_flow(f, 5, f.P.n_fluid);  // the walls at rest
  const auto div = check_exact_dissipation(f, 0.05);
  double wall_part = 0.0;
  for (std::size_t i = 0; i < f.P.n_fluid; ++i)
    if (f.w.x[1][i] < 2.0 * f.h) wall_part += std::abs((*div)[i]);
  REQUIRE(wall_part > 0.0);  // the rows beside the wall have a divergence the walls take part in
}

TEST_CASE("the viscous step limit counts a quarter of the bulk viscosity, with an implicit viscosity too", "[rhs]") {
  CflLimits cfl;
  cfl.kinematic_viscosity = 0.01;
  cfl.bulk_viscosity = 0.8;
  const double h = 0.04, inf = std::numeric_limits<double>::infinity();
  CHECK(cfl_step(cfl, inf, 0.0, h, true) == Approx(0.125 * h * h / (0.01 + 0.2)));
  // IMEX: the viscosity is implicit, the bulk viscosity is not.
  CHECK(cfl_step(cfl, inf, 0.0, h, false) == Approx(0.125 * h * h / 0.2));
  cfl.bulk_viscosity = 0.0;
  CHECK(cfl_step(cfl, inf, 0.0, h, false) == inf);
}
