// Moving wall bodies (core/wall_motion.hpp, Particles::wall_state): the exact positions, velocities
// and normals of rotating, oscillating and pitching walls at several times; today's rule untouched
// for walls without a motion; the solver placing walls by the same rule at each evaluation (with and
// without reordering), turned normals reaching the Morris wall model, the energy budget of the
// health check, the VTK writer and a restart from a checkpoint.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "sphmol/boundary/wall_pressure_extrapolated.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/run/checkpoint.hpp"
#include "sphmol/run/health_limits.hpp"
#include "sphmol/run/vtk_observer.hpp"
#include "sphmol/time/integrator.hpp"
#include "mini_xml.hpp"
#include "vtk_appended.hpp"

using namespace sphmol;
using std::numbers::pi;

namespace {

constexpr double kTol = 1e-13;

// N wall particles on a circle of radius R about c, normals pointing outward, all of body 0.
Particles<2> ring(int N, double R, std::array<double, 2> c, int fluid = 0) {
  Particles<2> P;
  for (int k = 0; k < fluid; ++k) P.add(Kind::Fluid, {c[0] + 0.1 * k, c[1]}, {0.0, 0.0}, 1.0, 1.0);
  for (int k = 0; k < N; ++k) {
    const double a = 2.0 * pi * k / N;
    P.add(Kind::Wall, {c[0] + R * std::cos(a), c[1] + R * std::sin(a)}, {0.0, 0.0}, 1.0, 1.0, {std::cos(a), std::sin(a)}, 0.0);
    P.body.back() = 0;
  }
  return P;
}

// A water-like test fluid; the settings of the Couette case.
Config fluid_config(double dx) {
  Config c;
  c.case_name = "wall_motion_test";
  c.dimension = 2;
  c.fluid.density = 1000.0;
  c.fluid.kinematic_viscosity = 1e-6;
  c.fluid.eos.type = "linear_relative";
  c.fluid.eos.sound_speed = 5e-3;
  c.fluid.body_force = {0.0, 0.0};
  c.discretization.spacing = dx;
  c.time.t_end = 1.0;
  return c;
}

// A block of fluid (perturbed velocities, so nothing is symmetric) beside a wall disc of body 0
// centred at the origin: the wall particles within 3 dx of the disc's edge, normals outward.
Particles<2> disc_and_fluid(double dx, double R) {
  Particles<2> P;
  const double m = 1000.0 * dx * dx;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 10; ++i) {
      const double x = -5 * dx + (i + 0.5) * dx, y = R + (j + 0.5) * dx;
      P.add(Kind::Fluid, {x, y}, {1e-5 * std::sin(0.7 * i + 1.3 * j), 1e-5 * std::cos(0.4 * i - 0.9 * j)}, m, 1000.0);
    }
  const int n = static_cast<int>(std::ceil(R / dx)) + 1;
  for (int j = -n; j <= n; ++j)
    for (int i = -n; i <= n; ++i) {
      const double x = (i + 0.5) * dx, y = (j + 0.5) * dx, r = std::hypot(x, y);
      if (r >= R || r < R - 3 * dx) continue;
      P.add(Kind::Wall, {x, y}, {0.0, 0.0}, m, 1000.0, {x / r, y / r}, R - r);
      P.body.back() = 0;
    }
  return P;
}

Domain<2> open_domain(double L) {
  Domain<2> d;
  d.lo = {-L, -L};
  d.hi = {L, L};
  return d;
}

}  // namespace

TEST_CASE("wall motion: walls without a motion keep today's rule, bit for bit", "[wall_motion]") {
  Particles<2> P;
  P.add(Kind::Fluid, {0.0, 0.0}, {0.0, 0.0}, 1.0, 1.0);
  P.add(Kind::Wall, {0.1, -0.2}, {0.3, 0.7}, 1.0, 1.0, {0.0, 1.0}, 0.05);
  P.add(Kind::Wall, {0.4, 1.2}, {1.0, 0.0}, 1.0, 1.0, {0.0, -1.0}, 0.05);
  P.stationary.back() = 1;  // a cavity lid
  REQUIRE(P.motion == std::vector<std::int32_t>{-1, -1, -1});
  for (double t : {0.0, 0.37, 12.5}) {
    for (int d = 0; d < 2; ++d) {
      CHECK(P.wall_position(d, 1, t) == P.x_ref[d][1] + P.v[d][1] * t);
      CHECK(P.wall_position(d, 2, t) == P.x_ref[d][2]);
      CHECK(P.wall_velocity(d, 1, t) == P.v[d][1]);
      CHECK(P.wall_velocity(d, 2, t) == P.v[d][2]);
      CHECK(P.wall_normal_at(d, 1, t) == P.wall_normal[d][1]);
    }
  }
  CHECK(!P.has_turning_walls());
  CHECK(P.max_wall_speed() == 1.0);  // the lid's, larger than hypot(0.3, 0.7)
}

TEST_CASE("wall motion: a rotating ring at several times, exact", "[wall_motion]") {
  const int N = 12;
  const double R = 0.25, omega = 1.7;
  const std::array<double, 2> c{0.3, -0.1};
  Particles<2> P = ring(N, R, c, 1);
  WallMotion<2> m;
  m.kind = WallMotionKind::rotation;
  m.centre = c;
  m.omega = omega;
  const auto k = P.attach_motion(0, m);
  CHECK(k == 0);
  CHECK(P.motion[0] == -1);  // the fluid particle follows no motion
  CHECK(P.has_turning_walls());
  CHECK(P.max_wall_speed() == Approx(omega * R));
  for (double t : {0.0, 0.4, 1.0, 3.3, 100.0}) {
    const auto frames = P.motion_frames(t);
    for (int q = 0; q < N; ++q) {
      const std::size_t i = 1 + q;
      const double a = 2.0 * pi * q / N + omega * t;
      const auto s = P.wall_state(i, t);
      const auto sf = P.wall_state(i, frames, t);
      INFO("t = " << t << ", particle " << q);
      CHECK(s.x[0] == Approx(c[0] + R * std::cos(a)).margin(kTol));
      CHECK(s.x[1] == Approx(c[1] + R * std::sin(a)).margin(kTol));
      CHECK(s.v[0] == Approx(-omega * R * std::sin(a)).margin(kTol));
      CHECK(s.v[1] == Approx(omega * R * std::cos(a)).margin(kTol));
      CHECK(s.n[0] == Approx(std::cos(a)).margin(kTol));  // the normal turns with the wall
      CHECK(s.n[1] == Approx(std::sin(a)).margin(kTol));
      for (int d = 0; d < 2; ++d) {
        CHECK(sf.x[d] == s.x[d]);  // one rule, through the frames or not
        CHECK(P.wall_position(d, i, t) == s.x[d]);
        CHECK(P.wall_velocity(d, i, t) == s.v[d]);
        CHECK(P.wall_normal_at(d, i, t) == s.n[d]);
      }
    }
  }
  // The velocity at t = 0 is the particle's recorded v.
  CHECK(P.v[1][1] == Approx(omega * R));
}

TEST_CASE("wall motion: a stationary rotating cylinder stays put and carries omega x r", "[wall_motion]") {
  const int N = 8;
  const double R = 0.5, omega = -2.0;
  Particles<2> P = ring(N, R, {0.0, 0.0});
  WallMotion<2> m;
  m.kind = WallMotionKind::rotation;
  m.omega = omega;
  m.stationary = true;
  P.attach_motion(0, m);
  CHECK(!P.has_turning_walls());
  for (double t : {0.0, 0.9, 7.0})
    for (int q = 0; q < N; ++q) {
      const auto s = P.wall_state(q, t);
      const double a = 2.0 * pi * q / N;
      CHECK(s.x[0] == P.x_ref[0][q]);
      CHECK(s.x[1] == P.x_ref[1][q]);
      CHECK(s.n[0] == P.wall_normal[0][q]);
      CHECK(s.n[1] == P.wall_normal[1][q]);
      CHECK(s.v[0] == Approx(-omega * R * std::sin(a)).margin(kTol));
      CHECK(s.v[1] == Approx(omega * R * std::cos(a)).margin(kTol));
    }
}

TEST_CASE("wall motion: a particle below a turning surface carries the surface's velocity", "[wall_motion]") {
  // Three layers of a cylinder of radius 1 (depths 0.05, 0.15, 0.25): each carries omega x 1 at the
  // foot of its normal, as the Morris wall model takes the wall particle's velocity for the surface's.
  for (const bool stationary : {false, true}) {
    Particles<2> P;
    for (int layer = 0; layer < 3; ++layer) {
      const double depth = 0.05 + 0.1 * layer, a = 0.4 * layer;
      P.add(Kind::Wall, {(1.0 - depth) * std::cos(a), (1.0 - depth) * std::sin(a)}, {0.0, 0.0}, 1.0, 1.0,
            {std::cos(a), std::sin(a)}, depth);
      P.body.back() = 0;
    }
    WallMotion<2> m;
    m.kind = WallMotionKind::rotation;
    m.omega = 3.0;
    m.stationary = stationary;
    P.attach_motion(0, m);
    CHECK(P.max_wall_speed() == Approx(3.0));
    for (double t : {0.0, 0.5, 2.0})
      for (int layer = 0; layer < 3; ++layer) {
        const double a = 0.4 * layer + (stationary ? 0.0 : 3.0 * t);
        const auto s = P.wall_state(layer, t);
        CHECK(s.v[0] == Approx(-3.0 * std::sin(a)).margin(kTol));
        CHECK(s.v[1] == Approx(3.0 * std::cos(a)).margin(kTol));
      }
  }
}

TEST_CASE("wall motion: an oscillating plate at several times, exact", "[wall_motion]") {
  Particles<2> P;
  for (int k = 0; k < 5; ++k) {
    P.add(Kind::Wall, {0.1 * k, -0.05}, {0.0, 0.0}, 1.0, 1.0, {0.0, 1.0}, 0.05);
    P.body.back() = 3;
  }
  WallMotion<2> m;
  m.kind = WallMotionKind::oscillation;
  m.amplitude = {0.02, -0.01};
  m.frequency = 2.5;
  m.phase = 0.3;
  P.attach_motion(3, m);
  const double w = 2.0 * pi * 2.5;
  CHECK(P.max_wall_speed() == Approx(w * std::hypot(0.02, 0.01)));
  CHECK(!P.has_turning_walls());
  for (double t : {0.0, 0.1, 0.25, 1.0 / 7.0, 4.0})
    for (std::size_t i = 0; i < 5; ++i) {
      const auto s = P.wall_state(i, t);
      const double sn = std::sin(w * t + 0.3), cs = std::cos(w * t + 0.3);
      CHECK(s.x[0] == Approx(P.x_ref[0][i] + 0.02 * sn).margin(kTol));
      CHECK(s.x[1] == Approx(P.x_ref[1][i] - 0.01 * sn).margin(kTol));
      CHECK(s.v[0] == Approx(0.02 * w * cs).margin(kTol));
      CHECK(s.v[1] == Approx(-0.01 * w * cs).margin(kTol));
      CHECK(s.n[0] == 0.0);
      CHECK(s.n[1] == 1.0);
    }
}

TEST_CASE("wall motion: a pitching tank turns by theta0 sin(2 pi f t) about its centre", "[wall_motion]") {
  Particles<2> P = ring(6, 1.0, {0.0, 0.0});
  WallMotion<2> m;
  m.kind = WallMotionKind::pitching;
  m.angle_amplitude = 0.2;
  m.frequency = 0.5;
  P.attach_motion(0, m);
  CHECK(P.has_turning_walls());
  CHECK(P.max_wall_speed() == Approx(0.2 * 2.0 * pi * 0.5));
  // t = 1/(4f) = 0.5 s: theta = theta0, at rest; t = 0: theta = 0, angular rate theta0 2 pi f.
  for (int q = 0; q < 6; ++q) {
    const double a = 2.0 * pi * q / 6;
    const auto top = P.wall_state(q, 0.5);
    CHECK(top.x[0] == Approx(std::cos(a + 0.2)).margin(kTol));
    CHECK(top.x[1] == Approx(std::sin(a + 0.2)).margin(kTol));
    CHECK(top.n[0] == Approx(std::cos(a + 0.2)).margin(kTol));
    CHECK(top.v[0] == Approx(0.0).margin(kTol));
    CHECK(top.v[1] == Approx(0.0).margin(kTol));
    const auto mid = P.wall_state(q, 0.0);
    CHECK(mid.x[0] == Approx(std::cos(a)).margin(kTol));
    CHECK(mid.v[0] == Approx(-0.2 * pi * std::sin(a)).margin(kTol));
    CHECK(mid.v[1] == Approx(0.2 * pi * std::cos(a)).margin(kTol));
    const auto back = P.wall_state(q, 1.5);  // theta = -theta0
    CHECK(back.x[1] == Approx(std::sin(a - 0.2)).margin(kTol));
  }
}

TEST_CASE("wall motion: 3D rotation about a tilted axis (Rodrigues)", "[wall_motion]") {
  Particles<3> P;
  P.add(Kind::Wall, {1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 1.0, 1.0, {0.0, 1.0, 0.0}, 0.0);
  P.add(Kind::Wall, {1.0, 2.0, 3.0}, {0.0, 0.0, 0.0}, 1.0, 1.0, {0.0, 0.0, 1.0}, 0.0);
  for (auto& b : P.body) b = 0;
  WallMotion<3> m;
  m.kind = WallMotionKind::rotation;
  m.axis = {2.0, 2.0, 2.0};  // normalised to (1, 1, 1)/sqrt(3)
  m.omega = 0.5;
  P.attach_motion(0, m);
  // A third of a turn about (1, 1, 1) maps (x, y, z) to (z, x, y).
  const double t = (2.0 * pi / 3.0) / 0.5;
  const auto a = P.wall_state(0, t), b = P.wall_state(1, t);
  CHECK(a.x[0] == Approx(0.0).margin(kTol));
  CHECK(a.x[1] == Approx(1.0).margin(kTol));
  CHECK(a.x[2] == Approx(0.0).margin(kTol));
  CHECK(a.n[0] == Approx(0.0).margin(kTol));
  CHECK(a.n[1] == Approx(0.0).margin(kTol));
  CHECK(a.n[2] == Approx(1.0).margin(kTol));
  CHECK(b.x[0] == Approx(3.0).margin(kTol));
  CHECK(b.x[1] == Approx(1.0).margin(kTol));
  CHECK(b.x[2] == Approx(2.0).margin(kTol));
  // v = omega k x (x - c), perpendicular to the axis and to the radius.
  const double s = 0.5 / std::sqrt(3.0);
  CHECK(a.v[0] == Approx(s * (1.0 * 0.0 - 1.0 * 1.0)).margin(kTol));
  CHECK(a.v[1] == Approx(s * (1.0 * 0.0 - 1.0 * 0.0)).margin(kTol));
  CHECK(a.v[2] == Approx(s * (1.0 * 1.0 - 1.0 * 0.0)).margin(kTol));
  // (1, 0, 0) is sqrt(2/3) from the axis.
  CHECK(P.motions[0].max_speed({1.0, 0.0, 0.0}) == Approx(0.5 * std::sqrt(2.0 / 3.0)));
}

// The wall acceleration of the extrapolated wall pressure (Adami et al. 2012, eq 27), against the
// derivatives of the motion: a central difference of a moving particle's velocity with a step of
// 1e-5 of the motion's period, and the closed forms of the stationary bodies' fields. At any
// frequency: it was a difference with a fixed step of 1e-6 s, zero at 0.5 and 1 MHz.
TEST_CASE("wall motion: the wall acceleration is the motion's at any frequency", "[wall_motion][walls]") {
  const auto acceleration = [](const Particles<2>& P, std::size_t i, double t) {
    const auto a = WallPressureExtrapolated<2>::wall_acceleration(P, i, t);
    REQUIRE(a.has_value());
    return *a;
  };
  for (const double f : {0.5, 3.0, 1e5, 5e5, 1e6}) {
    const double w = 2.0 * pi * f, period = 1.0 / f, t = 0.37 * period;
    const double dt = 1e-5 * period;
    // A particle 0.1 below the surface of a ring of radius 1 about (0.2, -0.3), each motion in turn.
    for (const auto kind : {WallMotionKind::oscillation, WallMotionKind::rotation, WallMotionKind::pitching})
      for (const bool stationary : {false, true}) {
        CAPTURE(f, static_cast<int>(kind), stationary);
        Particles<2> P;
        P.add(Kind::Wall, {0.2 + 0.9 * 0.6, -0.3 + 0.9 * 0.8}, {0.0, 0.0}, 1.0, 1.0, {0.6, 0.8}, 0.1);
        P.body.back() = 0;
        WallMotion<2> m;
        m.kind = kind;
        m.stationary = stationary;
        m.centre = {0.2, -0.3};
        m.amplitude = {0.01, -0.02};
        m.omega = w;
        m.angle_amplitude = 0.3;
        m.frequency = f;
        m.phase = 0.4;
        P.attach_motion(0, m);
        const auto a = acceleration(P, 0, t);
        const double scale = w * w;  // |a| ~ w^2 x (amplitude or radius)
        if (!stationary) {
          const auto up = P.wall_state(0, t + dt), down = P.wall_state(0, t - dt);
          for (int d = 0; d < 2; ++d) CHECK(a[d] == Approx((up.v[d] - down.v[d]) / (2.0 * dt)).margin(1e-7 * scale));
          continue;
        }
        // Fixed particles carrying the field v(x, t): dv/dt + (v . grad) v at the surface point r.
        const std::array<double, 2> r{0.6, 0.8};
        const double phi = w * t + 0.4;
        std::array<double, 2> expected{};
        if (kind == WallMotionKind::oscillation) expected = {-0.01 * w * w * std::sin(phi), 0.02 * w * w * std::sin(phi)};
        if (kind == WallMotionKind::rotation) expected = {-w * w * r[0], -w * w * r[1]};  // centripetal
        if (kind == WallMotionKind::pitching) {
          const double rate = 0.3 * w * std::cos(phi), change = -0.3 * w * w * std::sin(phi);
          expected = {-change * r[1] - rate * rate * r[0], change * r[0] - rate * rate * r[1]};
        }
        for (int d = 0; d < 2; ++d) CHECK(a[d] == Approx(expected[d]).margin(1e-12 * scale));
      }
  }
}

TEST_CASE("wall motion: the 3D wall acceleration of a turning body is the motion's", "[wall_motion][walls]") {
  for (const double f : {2.0, 1e6})
    for (const auto kind : {WallMotionKind::rotation, WallMotionKind::pitching}) {
      CAPTURE(f, static_cast<int>(kind));
      Particles<3> P;
      P.add(Kind::Wall, {1.0, 2.0, 0.5}, {0.0, 0.0, 0.0}, 1.0, 1.0, {0.0, 0.6, 0.8}, 0.05);
      P.body.back() = 0;
      WallMotion<3> m;
      m.kind = kind;
      m.axis = {1.0, 2.0, 2.0};
      m.centre = {0.1, 0.2, 0.3};
      m.omega = 2.0 * pi * f;
      m.angle_amplitude = 0.2;
      m.frequency = f;
      P.attach_motion(0, m);
      const double t = 0.29 / f, dt = 1e-5 / f;
      const auto a = WallPressureExtrapolated<3>::wall_acceleration(P, 0, t);
      REQUIRE(a.has_value());
      const auto up = P.wall_state(0, t + dt), down = P.wall_state(0, t - dt);
      const double scale = 4.0 * pi * pi * f * f;
      for (int d = 0; d < 3; ++d) CHECK((*a)[d] == Approx((up.v[d] - down.v[d]) / (2.0 * dt)).margin(1e-7 * scale));
    }
}

TEST_CASE("wall motion: invalid motions and attachments are errors", "[wall_motion]") {
  Particles<2> P = ring(4, 1.0, {0.0, 0.0}, 1);
  WallMotion<2> m;
  m.kind = WallMotionKind::oscillation;  // frequency 0
  CHECK_THROWS_WITH(P.attach_motion(0, m), Catch::Contains("frequency > 0"));
  m.frequency = 1.0;
  CHECK_THROWS_WITH(P.attach_motion(7, m), Catch::Contains("body 7 has no wall particles"));
  CHECK_THROWS_WITH(P.set_motion(0, -1), Catch::Contains("not a wall particle"));
  CHECK_THROWS_WITH(P.set_motion(1, 3), Catch::Contains("no motion 3"));
  m.amplitude[0] = std::nan("");
  CHECK_THROWS_WITH(P.add_motion(m), Catch::Contains("finite"));
  CHECK(P.motions.empty());
  WallMotion<1> r;
  r.kind = WallMotionKind::rotation;
  CHECK_THROWS_WITH(r.validated(), Catch::Contains("cannot rotate"));
  WallMotion<3> z;
  z.kind = WallMotionKind::rotation;
  z.axis = {0.0, 0.0, 0.0};
  CHECK_THROWS_WITH(z.validated(), Catch::Contains("axis"));
}

TEST_CASE("wall motion: the solver places walls by the rule at each evaluation, turned normals reach the wall model",
          "[wall_motion][rhs]") {
  const double dx = 1e-4, R = 6e-4, omega = 0.05;
  for (const bool reorder : {false, true}) {
    Config c = fluid_config(dx);
    c.discretization.reorder = reorder;
    Particles<2> P = disc_and_fluid(dx, R);
    WallMotion<2> m;
    m.kind = WallMotionKind::rotation;
    m.omega = omega;
    P.attach_motion(0, m);
    auto sys = assemble_system<2>(c, P, open_domain(1e-2), dx);
    std::vector<double> y = sys->initial_state(), ydot(y.size());
    for (double t : {0.0, 3.0, 11.0}) {  // 11 s: 0.55 rad, the disc's lattice is far from the fluid's
      sys->rhs(t, y.data(), ydot.data());
      const auto& order = sys->workspace_order();
      for (std::size_t k = P.n_fluid; k < P.size(); ++k) {
        const std::size_t i = order.empty() ? k : order[k];  // workspace k holds particle i
        const auto s = P.wall_state(i, t);
        for (int d = 0; d < 2; ++d) {
          REQUIRE(sys->positions()[d][k] == s.x[d]);
          REQUIRE(sys->velocities()[d][k] == s.v[d]);
        }
      }
    }
    // The same walls built where the rotation has taken them at t (normals turned, velocities
    // omega x r, staying put) give the same derivatives: positions, velocities and normals all
    // enter the terms as for any wall. With the reference normals (unturned) the Morris factor,
    // and so the viscous force, would differ.
    const double t = 11.0;
    Particles<2> Q = P;
    Q.motions.clear();
    for (std::size_t i = Q.n_fluid; i < Q.size(); ++i) {
      const auto s = P.wall_state(i, t);
      for (int d = 0; d < 2; ++d) {
        Q.x[d][i] = Q.x_ref[d][i] = s.x[d];
        Q.v[d][i] = s.v[d];
        Q.wall_normal[d][i] = s.n[d];
      }
      Q.motion[i] = -1;
      Q.stationary[i] = 1;
    }
    auto ref = assemble_system<2>(c, Q, open_domain(1e-2), dx);
    std::vector<double> yref = ref->initial_state(), dref(y.size());
    sys->rhs(t, y.data(), ydot.data());
    ref->rhs(t, yref.data(), dref.data());
    double scale = 0.0;
    for (double a : dref) scale = std::max(scale, std::abs(a));
    REQUIRE(scale > 0.0);
    for (std::size_t k = 0; k < y.size(); ++k) REQUIRE(ydot[k] == Approx(dref[k]).margin(1e-9 * scale));
    // And the unturned normals do change them (the check above can fail).
    Particles<2> U = Q;
    for (std::size_t i = U.n_fluid; i < U.size(); ++i)
      for (int d = 0; d < 2; ++d) U.wall_normal[d][i] = P.wall_normal[d][i];
    auto unturned = assemble_system<2>(c, U, open_domain(1e-2), dx);
    std::vector<double> du(y.size());
    unturned->rhs(t, yref.data(), du.data());
    double diff = 0.0;
    for (std::size_t k = 0; k < y.size(); ++k) diff = std::max(diff, std::abs(du[k] - dref[k]));
    CHECK(diff > 1e-3 * scale);
  }
}

TEST_CASE("wall motion: the energy budget allows for the work of a rotating wall", "[wall_motion][health]") {
  const double dx = 1e-4, R = 6e-4, omega = 0.05;
  const Config c = fluid_config(dx);
  Particles<2> still = disc_and_fluid(dx, R), turning = still;
  WallMotion<2> m;
  m.kind = WallMotionKind::rotation;
  m.omega = omega;
  turning.attach_motion(0, m);
  double mass = 0.0;
  for (std::size_t i = 0; i < still.n_fluid; ++i) mass += still.mass[i];
  double budget[2];
  for (int k = 0; k < 2; ++k) {
    auto sys = assemble_system<2>(c, k == 0 ? still : turning, open_domain(1e-2), dx);
    std::vector<double> y = sys->initial_state(), ydot(y.size());
    sys->rhs(0.0, y.data(), ydot.data());
    CHECK(sys->max_wall_speed() == Approx(k == 0 ? 0.0 : omega * R));
    budget[k] = health_limits<2>(c, 1e-5, false, *sys, y.data()).energy_budget;
  }
  // The walls' largest speed, omega R at the disc's surface, bounds the fluid's: M V^2 / 2 more.
  CHECK(budget[1] - budget[0] == Approx(0.5 * mass * (omega * R) * (omega * R)));
}

TEST_CASE("wall motion: the largest wall speed counts ghost walls and reads only the scene's own particles",
          "[wall_motion][health][ghost]") {
  // A box of fluid with ghost walls, the lid moving at 0.02 m/s: the generator appends images to
  // mass, rho and kind only, and the wall speed must come from its walls, not past the arrays.
  const double dx = 1e-4;
  Config c = fluid_config(dx);
  c.discretization.boundary = "ghost";
  c.discretization.wall_model = "prescribed";  // the Morris model needs wall particles
  Particles<2> P;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) P.add(Kind::Fluid, {(i + 0.5) * dx, (j + 0.5) * dx}, {0.0, 0.0}, 1000.0 * dx * dx, 1000.0);
  BoxWalls<2> walls{};
  for (int d = 0; d < 2; ++d)
    for (int side = 0; side < 2; ++side) walls[d][side] = {true, side * 8 * dx, true, {0.0, 0.0}};
  walls[1][1].velocity = {0.02, 0.0};
  Domain<2> dom;
  dom.hi = {8 * dx, 8 * dx};
  auto sys = assemble_system<2>(c, P, dom, dx, &walls);
  std::vector<double> y = sys->initial_state(), ydot(y.size());
  sys->rhs(0.0, y.data(), ydot.data());
  REQUIRE(sys->generated_particles() > 0);
  CHECK(sys->max_wall_speed() == 0.02);
}

TEST_CASE("wall motion: VTK files hold the walls where the solver places them", "[wall_motion][vtk][output]") {
  const double dx = 1e-4, R = 6e-4, omega = 0.05;
  Particles<2> P = disc_and_fluid(dx, R);
  WallMotion<2> m;
  m.kind = WallMotionKind::rotation;
  m.omega = omega;
  P.attach_motion(0, m);
  auto sys = assemble_system<2>(fluid_config(dx), P, open_domain(1e-2), dx);
  std::vector<double> y = sys->initial_state(), ydot(y.size());
  const double t = 7.0;
  sys->rhs(t, y.data(), ydot.data());
  const auto file = vtk_appended::read(vtp_file<2>(*sys, y.data(), t, VtkPart::walls));
  const auto* piece = file.root->child("PolyData")->child("Piece");
  REQUIRE(piece);
  const auto& xyz = file.of(vtk_appended::array_named(*piece->child("Points"), "Points"));
  const auto& vel = file.of(vtk_appended::array_named(*piece->child("PointData"), "velocity"));
  const std::size_t nw = P.size() - P.n_fluid;
  REQUIRE(xyz.size() == 3 * nw);
  for (std::size_t k = 0; k < nw; ++k) {
    const auto s = P.wall_state(P.n_fluid + k, t);
    for (int d = 0; d < 2; ++d) {
      CHECK(xyz[3 * k + d] == s.x[d]);
      CHECK(vel[3 * k + d] == s.v[d]);  // the velocity at t, not the one at t = 0
    }
  }
}

TEST_CASE("wall motion: a run restarted from a checkpoint places the walls as the uninterrupted run",
          "[wall_motion][checkpoint]") {
  const double dx = 1e-4, R = 6e-4;
  Config c = fluid_config(dx);
  c.time.integrator = "leapfrog";
  c.time.dt = 2e-3;
  Particles<2> P = disc_and_fluid(dx, R);
  WallMotion<2> m;
  m.kind = WallMotionKind::pitching;
  m.angle_amplitude = 0.3;
  m.frequency = 2.0;
  P.attach_motion(0, m);
  const double t1 = 0.1, t2 = 0.16;
  auto a = assemble_system<2>(c, P, open_domain(1e-2), dx);
  std::vector<double> ya = a->initial_state();
  auto Ia = make_integrator(c.time);
  Ia->initialize(*a, 0.0, ya.data());
  Ia->advance(t1);
  Checkpoint cp;
  cp.case_name = c.case_name;
  cp.dimension = 2;
  cp.t = t1;
  cp.y = ya;
  cp.integrator = Ia->name();
  cp.integrator_state = Ia->save_state();
  const auto dir = std::filesystem::temp_directory_path() / ("sphmol-wall-motion-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::vector<std::string> written;
  const std::string path = write_checkpoint(dir.string(), cp, "case: wall_motion_test\n", written);
  Ia->advance(t2);

  const Checkpoint back = read_checkpoint(path);
  std::filesystem::remove_all(dir);
  REQUIRE(back.t == t1);
  auto b = assemble_system<2>(c, P, open_domain(1e-2), dx);
  std::vector<double> yb = back.y;
  auto Ib = make_integrator(c.time);
  Ib->initialize(*b, back.t, yb.data());
  Ib->restore_state(back.integrator_state);
  Ib->advance(t2);
  // Both evaluated at t2 from their states: the walls are where the uninterrupted run has them.
  std::vector<double> da(ya.size()), db(yb.size());
  a->rhs(t2, ya.data(), da.data());
  b->rhs(t2, yb.data(), db.data());
  for (std::size_t k = P.n_fluid; k < P.size(); ++k)
    for (int d = 0; d < 2; ++d) {
      REQUIRE(a->positions()[d][k] == b->positions()[d][k]);
      REQUIRE(b->positions()[d][k] == P.wall_state(k, t2).x[d]);
      REQUIRE(a->velocities()[d][k] == b->velocities()[d][k]);
    }
  // The fluid too, up to the round-off of the restarted step times.
  for (std::size_t k = 0; k < ya.size(); ++k) REQUIRE(ya[k] == Approx(yb[k]).epsilon(1e-9).margin(1e-15));
}

TEST_CASE("assembly: the Morris wall model with ghost walls is refused, not run past the wall arrays", "[boundary][ghost]") {
  // Before: assembled, and the Morris term read wall_depth and wall_normal at ghost image indices
  // beyond the particles' arrays (an ASan heap-buffer-overflow).
  const double dx = 1e-4;
  Config c = fluid_config(dx);
  c.discretization.boundary = "ghost";
  c.discretization.wall_model = "morris";
  Particles<2> P;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) P.add(Kind::Fluid, {(i + 0.5) * dx, (j + 0.5) * dx}, {0.0, 0.0}, 1000.0 * dx * dx, 1000.0);
  BoxWalls<2> walls{};
  for (int d = 0; d < 2; ++d)
    for (int side = 0; side < 2; ++side) walls[d][side] = {true, side * 4 * dx, true, {0.0, 0.0}};
  Domain<2> dom;
  dom.hi = {4 * dx, 4 * dx};
  CHECK_THROWS_WITH(assemble_system<2>(c, P, dom, dx, &walls), Catch::Contains("discretization.wall_model: morris needs boundary: wall_particles"));
}
