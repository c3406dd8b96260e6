// Force probes on wall bodies: in a 2D tank of water at hydrostatic rest the floor carries
// rho g H x width and a side wall rho g H^2 / 2 (per unit depth); and, for any velocity field, the
// forces on all bodies together are exactly minus the wall-pair forces the RHS gives the fluid
// (sum_i m_i (dv_i/dt - g)), for each momentum form and viscosity the probe supports.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "sphmol/kernels/registry.hpp"
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

Tank make_tank(const Config& c, double speed) {
  Tank t;
  Domain<2> dom;
  dom.lo = {-1, -1};
  dom.hi = {2, 2};
  Particles<2> P = tank();
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
  const auto& P = t.sys->particles();
  const auto& L = t.sys->layout();
  // sum_i m_i dv_i/dt = sum_i m_i g + (wall pairs); the fluid-fluid pairs cancel in pairs.
  std::array<double, 2> on_fluid{};
  double scale = 0.0;
  for (std::size_t i = 0; i < P.n_fluid; ++i)
    for (int d = 0; d < 2; ++d) {
      const double a = t.ydot[L.velocity(d) + i] - c.fluid.body_force[d];
      on_fluid[d] += P.mass[i] * a;
      scale += P.mass[i] * std::abs(a);
    }
  std::array<double, 2> on_walls{};
  for (int b = 0; b < 5; ++b) {
    const auto f = body_force(t, b);
    for (int d = 0; d < 2; ++d) on_walls[d] += f[d];
  }
  for (int d = 0; d < 2; ++d) CHECK(on_walls[d] == Approx(-on_fluid[d]).margin(1e-9 * scale));
}
