// The generalised wall boundary of Adami, Hu & Adams (2012): the no-slip wall velocity of the viscous
// term (boundary/adami_wall_velocity.hpp) and the wall pressure with the wall's acceleration
// (boundary/wall_pressure_extrapolated.hpp), on a lattice of fluid above three wall rows.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "sphmol/boundary/adami_wall_velocity.hpp"
#include "sphmol/boundary/wall_pressure_extrapolated.hpp"
#include "sphmol/kernels/wendland_c2.hpp"
#include "sphmol/physics/morris_viscosity.hpp"
#include "sphmol/scenes/lattice_mass.hpp"

#include "config_test_base.hpp"
#include "sphmol/config/config.hpp"
#include "workspace_pairs.hpp"

using namespace sphmol;

namespace {

// n x n fluid lattice in [0, 1) x [0, 1), periodic in x, over `layers` wall rows below y = 0.
struct WallFixture {
  Particles<2> P;
  Domain<2> dom;
  Workspace<2> w;
  PairList verlet;
  std::array<std::vector<double>, 2> dxdt, dvdt;
  double dx, h, rho0 = 1000.0;

  explicit WallFixture(int n, int layers = 3) {
    dx = 1.0 / n;
    h = 2.0 * dx;
    const double m = lattice_particle_mass<2>("wendland_c2", rho0, dx, h);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) P.add(Kind::Fluid, {(i + 0.5) * dx, (j + 0.5) * dx}, {0, 0}, m, rho0);
    for (int k = 0; k < layers; ++k)
      for (int i = 0; i < n; ++i) P.add(Kind::Wall, {(i + 0.5) * dx, -(k + 0.5) * dx}, {0, 0}, m, rho0, {0.0, 1.0}, (k + 0.5) * dx);
    dom.lo = {0.0, -layers * dx};
    dom.hi = {1.0, 1.0 + 4.0 * h};
    dom.periodic = {true, false};
    load_workspace(w, P, dom, h);
    for (int d = 0; d < 2; ++d) {
      dxdt[d].assign(P.n_fluid, 0.0);
      dvdt[d].assign(P.n_fluid, 0.0);
      w.dxdt[d] = dxdt[d].data();
      w.dvdt[d] = dvdt[d].data();
    }
  }
  void pairs() { build_workspace_pairs<2, WendlandC2Kernel<2>>(w, P, dom, 2.0 * h * 1.1, verlet); }
  // The Shepard-weighted fluid average of field f at wall particle i, summed here independently of the term.
  template <class F>
  double shepard(std::size_t i, F f) const {
    double s = 0.0, sw = 0.0;
    for (std::size_t j = 0; j < P.n_fluid; ++j) {
      const double r = std::hypot(dom.min_image(0, w.x[0][i] - w.x[0][j]), w.x[1][i] - w.x[1][j]);
      const double W = WendlandC2Kernel<2>::W(r, h);
      s += f(j) * W;
      sw += W;
    }
    return s / sw;
  }
};

}  // namespace

TEST_CASE("Adami wall velocity mirrors the Shepard-interpolated fluid velocity about the wall's", "[walls]") {
  WallFixture f(20);
  const double gamma = 0.7, U = 0.3;  // fluid u = gamma y; wall moving at U along x
  for (std::size_t i = 0; i < f.P.n_fluid; ++i) {
    f.w.v[0][i] = gamma * f.w.x[1][i];
    f.w.v[1][i] = 0.1;
  }
  for (std::size_t i = f.P.n_fluid; i < f.w.n; ++i) f.w.v[0][i] = U;
  f.pairs();
  AdamiWallVelocity<2>().apply(f.w);
  REQUIRE(f.w.v_viscous[0].size() == f.w.n);
  std::size_t with_fluid = 0;
  for (std::size_t i = 0; i < f.w.n; ++i) {
    if (i < f.P.n_fluid || f.w.pairs.offset[i + 1] == f.w.pairs.offset[i]) {
      // Fluid, and walls out of reach of the fluid: their own velocity.
      CHECK(f.w.v_viscous[0][i] == f.w.v[0][i]);
      CHECK(f.w.v_viscous[1][i] == f.w.v[1][i]);
      continue;
    }
    ++with_fluid;
    const double ux = f.shepard(i, [&](std::size_t j) { return f.w.v[0][j]; });
    CHECK(f.w.v_viscous[0][i] == Approx(2.0 * U - ux).epsilon(1e-12));
    CHECK(f.w.v_viscous[1][i] == Approx(-0.1).epsilon(1e-12));
  }
  CHECK(with_fluid == 20 * 3);  // support 4 dx: all three rows see the fluid
  // The walls' own velocities are untouched (continuity and pressure read them).
  for (std::size_t i = f.P.n_fluid; i < f.w.n; ++i) CHECK(f.w.v[0][i] == U);
}

TEST_CASE("Adami wall velocity holds a linear shear at the wall where prescribed wall velocities do not", "[walls]") {
  // u = gamma y has no curvature: nu lap u = 0 at every fluid particle, first rows included, if the
  // walls continue the profile. Walls at their own u = 0 stand for u = 0 over the whole wall depth,
  // a kink at y = 0 that drags the first rows; the mirrored velocities remove most of it. Mirroring
  // the Shepard average (taken about 1.5 spacings into the fluid) is not exact for a linear profile:
  // measured 0.081 (0.41 nu gamma / dx) prescribed against 0.0083 mirrored, a tenth.
  const double gamma = 1.0, nu = 1e-2;
  const auto first_row_force = [&](bool adami) {
    WallFixture f(20);
    for (std::size_t i = 0; i < f.P.n_fluid; ++i) f.w.v[0][i] = gamma * f.w.x[1][i];
    f.pairs();
    if (adami) AdamiWallVelocity<2>().apply(f.w);
    MorrisViscosity<2>(nu * f.rho0).apply(f.w);
    return std::abs(f.dvdt[0][5]);  // a particle of the first row (y = dx/2)
  };
  const double prescribed = first_row_force(false), mirrored = first_row_force(true);
  // Scale: nu gamma / dx, the viscous acceleration of a kink of gamma over one spacing.
  const double scale = nu * gamma * 20.0;
  CHECK(prescribed > 0.3 * scale);
  CHECK(mirrored < 0.15 * prescribed);
}

TEST_CASE("extrapolated wall pressure carries the wall's acceleration (Adami et al. 2012, eq. 27)", "[walls]") {
  // Fluid at uniform pressure p0 without gravity. A wall accelerating into the fluid must push it:
  // p_w = p0 + rho0 a . sum (x_f - x_w) W / sum W > p0. A wall at rest or a belt (lid) keeps p0.
  const double p0 = 50.0, A = 1e-3, freq = 2.0, phase = 0.3;
  const auto run = [&](bool oscillate, double t) {
    WallFixture f(20);
    WallMotion<2> m;
    m.kind = WallMotionKind::oscillation;
    m.amplitude = {0.0, A};
    m.frequency = freq;
    m.phase = phase;
    if (!oscillate) {
      m.kind = WallMotionKind::translation;
      m.stationary = true;
      m.velocity = {1.0, 0.0};
    }
    const auto k = f.P.add_motion(m);
    for (std::size_t i = f.P.n_fluid; i < f.w.n; ++i) f.P.set_motion(i, k);
    f.w.t = t;
    f.pairs();
    for (std::size_t i = 0; i < f.w.n; ++i) f.w.p[i] = p0;
    WallPressureExtrapolated<2>({0.0, 0.0}, 0.0, [&](double p) { return f.rho0 + p / 100.0; }).apply(f.w);
    std::vector<double> expected(f.w.n, p0);
    const double w = 2.0 * std::numbers::pi * freq;
    const double ay = -A * w * w * std::sin(w * t + phase);  // the oscillation's acceleration
    for (std::size_t i = f.P.n_fluid; i < f.w.n; ++i) {
      const double lever = f.shepard(i, [&](std::size_t j) { return f.w.x[1][j] - f.w.x[1][i]; });
      expected[i] = p0 + (oscillate ? f.rho0 * ay * lever : 0.0);
    }
    return std::make_pair(std::vector<double>(f.w.p.begin() + f.P.n_fluid, f.w.p.end()),
                          std::vector<double>(expected.begin() + f.P.n_fluid, expected.end()));
  };
  // t where sin(w t + phase) = -1: the wall accelerates upwards, into the fluid, at A w^2.
  const double t_up = (1.5 * std::numbers::pi - phase) / (2.0 * std::numbers::pi * freq);
  const auto [p, expected] = run(true, t_up);
  for (std::size_t k = 0; k < p.size(); ++k) {
    CHECK(expected[k] > p0 + 1e-3);
    CHECK(p[k] == Approx(expected[k]).epsilon(1e-7));
  }
  const auto [pb, eb] = run(false, t_up);
  for (std::size_t k = 0; k < pb.size(); ++k) CHECK(pb[k] == Approx(p0).epsilon(1e-14));
}

TEST_CASE("config: wall_model adami brings the extrapolated wall pressure and refuses what would replace it", "[walls][config]") {
  const std::string cavity = "case: cavity\nfluid:\n  density: 1\n  kinematic_viscosity: 0.01\n  eos:\n    sound_speed: 10\n"
                             "geometry:\n  box: [1, 1]\n  wall_velocity: 1\ndiscretization:\n  particles_across: 20\n"
                             "time:\n  t_end: 1\n";
  const auto c = load_config_string(cavity, {"discretization.wall_model=adami"});
  CHECK(c.discretization.wall_model == "adami");
  CHECK(c.discretization.wall_pressure == "extrapolated");
  CHECK(load_config_string(cavity, {"discretization.wall_model=adami", "discretization.wall_pressure=extrapolated"})
            .discretization.wall_pressure == "extrapolated");
  using Catch::Matchers::Contains;
  CHECK_THAT(config_test::error_of(cavity, {"discretization.wall_model=adami", "discretization.wall_pressure=rest"}),
             Contains("discretization.wall_pressure: wall_model: adami extrapolates the wall pressure"));
  CHECK_THAT(config_test::error_of(cavity, {"discretization.wall_model=adami", "discretization.viscosity=strain_rate"}),
             Contains("discretization.wall_model: adami's no-slip wall velocity"));
  CHECK_THAT(config_test::error_of(cavity, {"discretization.wall_model=adami", "discretization.boundary=ghost"}),
             Contains("discretization.wall_model: adami extrapolates through wall particles"));
}
