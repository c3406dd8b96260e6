// Force probes on wall bodies: in a 2D tank of water at hydrostatic rest the floor carries
// rho g H x width and a side wall rho g H^2 / 2 (per unit depth); and, for any velocity field, the
// forces on all bodies together are exactly minus the wall-pair forces the RHS gives the fluid
// (sum_i m_i (dv_i/dt - g)), for each momentum form and viscosity the probe supports; also when the
// walls follow a prescribed motion and the probe (ProbeObserver) samples at a time t > 0, where the
// walls' velocities and normals are not their t = 0 ones.
#include <unistd.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "sphmol/kernels/registry.hpp"
#include "sphmol/probes/probe_observer.hpp"
#include "sphmol/probes/wall_force.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "probe_tank.hpp"

using namespace sphmol;

namespace {

using namespace probe_tank;

struct Tank {
  std::unique_ptr<SphSystem<2>> sys;
  std::vector<double> y, ydot;
  WallForceModel model;
  KernelInfo<2> K;
};

// motion: every wall particle follows it (none: the walls stand still).
Tank make_tank(const Config& c, double speed, const WallMotion<2>* motion = nullptr) {
  Tank t;
  Domain<2> dom;
  dom.lo = {-1, -1};
  dom.hi = {2, 2};
  Particles<2> P = tank();
  if (motion) {
    const auto k = P.add_motion(*motion);
    for (std::size_t j = P.n_fluid; j < P.size(); ++j) P.set_motion(j, k);
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-speed, speed);
  for (std::size_t i = 0; i < P.n_fluid; ++i)
    for (int d = 0; d < 2; ++d) P.v[d][i] = u(rng);
  t.sys = assemble_system<2>(c, std::move(P), dom, kDx);
  t.y = t.sys->initial_state();
  t.ydot.resize(t.y.size());
  t.sys->rhs(0.0, t.y.data(), t.ydot.data());  // also fills the density, pressure and sound speed
  const auto& d = c.discretization;
  t.model.momentum_116 = d.momentum == "symmetric_116";
  t.model.viscous = d.viscosity == "morris";
  t.model.dynamic_viscosity = c.fluid.density * c.fluid.kinematic_viscosity;
  t.model.morris_wall_velocity = d.wall_model == "morris";
  t.model.beta_max = d.wall_beta_max;
  t.model.artificial_viscosity = d.artificial_viscosity.enabled;
  t.model.pi = {d.artificial_viscosity.alpha, d.artificial_viscosity.beta, d.artificial_viscosity.eta,
                d.artificial_viscosity.band_width(), d.artificial_viscosity.band_offset()};
  t.K = kernel_info<2>(d.kernel);
  return t;
}

std::array<double, 2> body_force(const Tank& t, int body) {
  const auto& P = t.sys->particles();
  const auto& L = t.sys->layout();
  std::array<std::vector<double>, 2> x, v;
  WallForceState<2> s;
  for (int d = 0; d < 2; ++d) {
    for (std::size_t i = 0; i < P.size(); ++i) {
      x[d].push_back(i < P.n_fluid ? t.y[L.position(d) + i] : P.wall_position(d, i, 0.0));
      v[d].push_back(i < P.n_fluid ? t.y[L.velocity(d) + i] : P.v[d][i]);
    }
    s.x[d] = x[d].data();
    s.v[d] = v[d].data();
  }
  s.rho = t.sys->density().data();
  s.p = t.sys->pressure().data();
  s.c = t.sys->sound_speed().data();
  return wall_body_force<2>(P, s, body, t.K.dWdr, t.sys->smoothing_length(), t.K.support, t.sys->domain(), t.model);
}

// sum_i m_i (dv_i/dt - g) over the fluid, and its scale sum_i m_i |dv_i/dt - g| (per axis, summed).
std::pair<std::array<double, 2>, double> on_fluid(const Tank& t, const Config& c) {
  const auto& P = t.sys->particles();
  const auto& L = t.sys->layout();
  std::array<double, 2> f{};
  double scale = 0.0;
  for (std::size_t i = 0; i < P.n_fluid; ++i)
    for (int d = 0; d < 2; ++d) {
      const double a = t.ydot[L.velocity(d) + i] - c.fluid.body_force[d];
      f[d] += P.mass[i] * a;
      scale += P.mass[i] * std::abs(a);
    }
  return {f, scale};
}

struct TempDir {
  std::filesystem::path path;
  TempDir() {
    path = std::filesystem::temp_directory_path() /
           ("sphmol-force-probe-" + std::to_string(::getpid()) + "-" + std::to_string(reinterpret_cast<std::uintptr_t>(this)));
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

}  // namespace

TEST_CASE("force probe: hydrostatic loads on a tank's floor and side walls", "[probes][force]") {
  const Tank t = make_tank(tank_config(), 0.0);
  const double floor = kRho0 * kG * kH * kW, side = kRho0 * kG * kH * kH / 2;
  const auto f0 = body_force(t, 0), f1 = body_force(t, 1), f2 = body_force(t, 2), f3 = body_force(t, 3),
             f4 = body_force(t, 4);
  INFO("floor " << f0[0] << ", " << f0[1] << "; left " << f1[0] << ", " << f1[1] << "; right " << f2[0]
                << "; left corner " << f3[0] << ", " << f3[1] << " (exact: floor and corners " << -floor
                << " down, each side wall with its corner " << side << " outwards)");
  CHECK(f0[1] + f3[1] + f4[1] == Approx(-floor).epsilon(0.005));
  CHECK(f1[0] + f3[0] == Approx(-side).epsilon(0.01));
  CHECK(f2[0] + f4[0] == Approx(side).epsilon(0.01));
}

TEST_CASE("force probe: the bodies receive minus what the fluid receives from them", "[probes][force]") {
  Config c = tank_config();
  SECTION("eq 117, Morris viscosity, prescribed wall velocity") {}
  SECTION("eq 117, Morris viscosity, Morris wall velocity") { c.discretization.wall_model = "morris"; }
  SECTION("eq 116, Morris viscosity") { c.discretization.momentum = "symmetric_116"; }
  SECTION("eq 117, artificial viscosity, no laminar viscosity") {
    c.discretization.viscosity = "none";
    c.discretization.artificial_viscosity.enabled = true;
  }
  // Random velocities up to 0.5 m/s, so the viscous pair forces are as large as the pressure's.
  const Tank t = make_tank(c, 0.5);
  // sum_i m_i dv_i/dt = sum_i m_i g + (wall pairs); the fluid-fluid pairs cancel in pairs.
  const auto [fluid, scale] = on_fluid(t, c);
  std::array<double, 2> on_walls{};
  for (int b = 0; b < 5; ++b) {
    const auto f = body_force(t, b);
    for (int d = 0; d < 2; ++d) on_walls[d] += f[d];
  }
  // An absolute bound: Approx would also pass anything within its relative epsilon (1.2e-5).
  for (int d = 0; d < 2; ++d) CHECK(std::abs(on_walls[d] + fluid[d]) <= 1e-9 * scale);
}

TEST_CASE("force probe: on walls that follow a motion, the probe at t reads the walls' velocities and normals at t",
          "[probes][force][wall_motion]") {
  // Every wall pitches about the tank's centre, theta(t) = theta0 sin(2 pi f t): at t = 1/8 s its
  // angular rate is cos(pi/4) of the one at t = 0 and its normals have turned by 0.7 theta0, so a
  // probe that read the walls' t = 0 velocities (Particles::v) or as-built normals would not
  // balance the pair forces the RHS gives the fluid at t.
  WallMotion<2> m;
  m.kind = WallMotionKind::pitching;
  m.centre = {0.5 * kW, 0.5 * kH};
  m.angle_amplitude = 0.01;  // the far corners move by 0.2 spacings at most: no wall reaches the fluid
  m.frequency = 1.0;
  const double t_sample = 0.125;
  Config c = tank_config();
  SECTION("eq 117, Morris viscosity, prescribed wall velocity") {}
  SECTION("eq 117, Morris viscosity, Morris wall velocity (the turned normals)") { c.discretization.wall_model = "morris"; }
  SECTION("eq 117, artificial viscosity, no laminar viscosity") {
    c.discretization.viscosity = "none";
    c.discretization.artificial_viscosity.enabled = true;
  }
  c.time.t_end = 1.0;
  c.output.times = {1.0};
  for (int b = 0; b < 5; ++b) {
    ProbeConfig p;
    p.name = "body" + std::to_string(b);
    p.type = "force";
    p.body = p.name;
    p.body_index = b;
    p.where = "case.yaml:7: probes[" + std::to_string(b) + "]";
    c.probes.push_back(p);
  }
  Tank t = make_tank(c, 0.5, &m);
  // The walls' velocities at t differ from those at t = 0 (else the test would show nothing).
  const auto& P = t.sys->particles();
  const std::size_t corner = P.size() - 1;
  REQUIRE(std::abs(P.wall_velocity(0, corner, t_sample) - P.v[0][corner]) > 1e-3);
  t.sys->rhs(t_sample, t.y.data(), t.ydot.data());  // the fields at t, which the probe reads
  const auto [fluid, scale] = on_fluid(t, c);

  TempDir dir;
  OutputSink out{dir.path.string(), true};
  ProbeObserver<2> obs(c, *t.sys);
  std::map<std::string, std::vector<double>> sampled;
  obs.on_sample = [&](const std::string& name, double, const std::vector<double>& v) { sampled[name] = v; };
  obs.at_output(*t.sys, t.y.data(), t_sample, out);
  REQUIRE(sampled.size() == 5);
  std::array<double, 2> on_walls{};
  for (const auto& [name, f] : sampled) {
    REQUIRE(f.size() == 2);
    for (int d = 0; d < 2; ++d) on_walls[d] += f[d];
  }
  INFO("walls " << on_walls[0] << ", " << on_walls[1] << "; fluid " << fluid[0] << ", " << fluid[1] << "; scale " << scale);
  // An absolute bound, not Approx: its default relative epsilon (100 float epsilons, 1.2e-5 of
  // 5900 N/m) would pass the as-built normals' error under the Morris wall velocity (8e-5 N/m in x,
  // 1.4e-3 N/m in y here); the sums agree to round-off (1e-11 N/m).
  for (int d = 0; d < 2; ++d) CHECK(std::abs(on_walls[d] + fluid[d]) <= 1e-9 * scale);
}
