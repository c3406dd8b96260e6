// The physical bounds of the per-step health check (run/health_limits.hpp, run/health_check.hpp):
// derived from the scene, and each one ends a state that crosses it with a named BlowUp.
#include <catch2/catch.hpp>

#include <omp.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/run/health_check.hpp"
#include "sphmol/run/health_limits.hpp"

using namespace sphmol;

namespace {

Config shipped(const std::string& name, const std::vector<std::string>& set = {}) {
  return load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/" + name + ".yaml", set);
}

// The cause of the BlowUp the check throws for state y, or "" when the state passes.
std::string cause_of(HealthCheck<2>& check, const std::vector<double>& y) {
  try {
    check(1e-3, y.data(), 1e-3);
  } catch (const BlowUp& b) {
    return b.cause;
  }
  return "";
}

// A shipped case built, its RHS evaluated at the initial state (the densities the check reads), and
// the health limits of the scene.
struct Evaluated {
  Config c;
  std::unique_ptr<Case<2>> cs;
  std::unique_ptr<SphSystem<2>> sys;
  std::vector<double> y0;
  HealthLimits lim;
  explicit Evaluated(Config config) : c(std::move(config)), cs(make_case<2>(c)), sys(cs->build(c)), y0(sys->initial_state()) {
    std::vector<double> ydot(y0.size());
    sys->rhs(0.0, y0.data(), ydot.data());
    lim = health_limits<2>(c, cs->velocity_scale(c), cs->free_surface(), *sys, y0.data());
  }
};

}  // namespace

TEST_CASE("health limits: velocity scales come from the scene", "[health]") {
  // Each case declares its scale after building its scene (Case::velocity_scale).
  const auto scale = [](const std::string& file, const std::string& name, int dim = 2) {
    const Config c = shipped(file);
    if (dim == 1) {
      auto k = make_case<1>(c);
      k->build(c);
      return std::pair{k->velocity_scale(c), k->free_surface()};
    }
    auto k = make_case<2>(c);
    k->build(c);
    return std::pair{k->velocity_scale(c), k->free_surface()};
  };
  CHECK(scale("couette", "couette").first == 2.5e-5);
  // F l^2 / (8 nu): the steady centre-line speed.
  CHECK(scale("poiseuille", "poiseuille").first == Approx(2.5e-5));
  CHECK(scale("taylor_green", "taylor_green").first == 1.0);
  CHECK(scale("cavity", "cavity").first == 1.0);
  CHECK(scale("hydrostatic", "hydrostatic").first == Approx(std::sqrt(2 * 9.81 * 0.9)));
  CHECK(scale("hydrostatic", "hydrostatic").second);
  CHECK(scale("dam_break", "dam_break").first == Approx(std::sqrt(2 * 9.81 * 2.0)));
  CHECK(scale("dam_break", "dam_break").second);
  CHECK(scale("shock_tube_1d", "shock_tube", 1) == std::pair{0.0, false});
}

TEST_CASE("health check: kinetic energy gain, speed and density bounds end the run with a named cause", "[health]") {
  const Config c = shipped("taylor_green", {"discretization.particles_across=16"});
  auto cs = make_case<2>(c);
  auto sys = cs->build(c);
  std::vector<double> y0 = sys->initial_state(), ydot(y0.size());
  sys->rhs(0.0, y0.data(), ydot.data());
  const HealthLimits lim = health_limits<2>(c, cs->velocity_scale(c), cs->free_surface(), *sys, y0.data());
  CHECK(lim.max_speed == 10.0);  // 10 U = c = 10 m/s: the sound speed
  CHECK(lim.max_compression == Approx(0.2));
  CHECK(lim.max_expansion == Approx(0.2));  // no free surface
  HealthCheck<2> check(*sys, y0.data(), 0.0, lim);
  const auto& L = sys->layout();

  CHECK(cause_of(check, y0) == "");
  // Every velocity x 1.1: 21 % more kinetic energy than the initial state had, and no input.
  std::vector<double> y = y0;
  for (int d = 0; d < 2; ++d)
    for (std::size_t i = 0; i < L.n; ++i) y[L.velocity(d) + i] *= 1.1;
  CHECK(cause_of(check, y).rfind("kinetic energy ", 0) == 0);
  // 5 % more stays inside the 10 % slack.
  y = y0;
  for (int d = 0; d < 2; ++d)
    for (std::size_t i = 0; i < L.n; ++i) y[L.velocity(d) + i] *= std::sqrt(1.05);
  CHECK(cause_of(check, y) == "");
  // One particle at Mach 1.5.
  y = y0;
  y[L.velocity(0) + 7] = 15.0;
  y[L.velocity(1) + 7] = 0.0;
  const std::string speed = cause_of(check, y);
  CHECK(speed.rfind("speed 15 m/s above 10 m/s, the sound speed c = 10 m/s", 0) == 0);

  // Densities are those of the latest RHS evaluation: compress the lattice by 20 % in x.
  y = y0;
  for (std::size_t i = 0; i < L.n; ++i) y[L.position(0) + i] *= 0.75;
  sys->rhs(0.0, y.data(), ydot.data());
  const std::string rho = cause_of(check, y);
  INFO(rho);
  CHECK(rho.rfind("density ratio rho/rho0 = ", 0) == 0);
}

TEST_CASE("health limits: free surfaces bound compression only, ideal gases have no speed or density bound", "[health]") {
  {
    const Config c = shipped("hydrostatic", {"discretization.particles_across=10"});
    auto cs = make_case<2>(c);
    auto sys = cs->build(c);
    const auto y0 = sys->initial_state();
    const HealthLimits lim = health_limits<2>(c, cs->velocity_scale(c), cs->free_surface(), *sys, y0.data());
    CHECK(std::isinf(lim.max_expansion));
    CHECK(lim.max_compression == Approx(std::max(0.2, 10 * 2 * 9.81 * 0.9 / (59.4 * 59.4))));
    CHECK(lim.max_speed == Approx(10 * std::sqrt(2 * 9.81 * 0.9)));  // 10 sqrt(2 g H) = 42 m/s, below c = 59.4 m/s
    CHECK(lim.g[1] == -9.81);
  }
  {
    const Config c = shipped("shock_tube_1d");
    auto cs = make_case<1>(c);
    auto sys = cs->build(c);
    const auto y0 = sys->initial_state();
    const HealthLimits lim = health_limits<1>(c, cs->velocity_scale(c), cs->free_surface(), *sys, y0.data());
    CHECK(std::isinf(lim.max_speed));
    CHECK(lim.rho0 == 0.0);
    CHECK(lim.energy_budget > 0.0);  // the internal energy
  }
}

TEST_CASE("health limits: elastic energy of the EOS is int p / rho^2 d rho, zero at rho0, never negative", "[health]") {
  for (const auto kind : {HealthLimits::Elastic::Kind::linear, HealthLimits::Elastic::Kind::tait}) {
    HealthLimits::Elastic e;
    e.kind = kind;
    e.rho0 = 1000.0;
    e.c2 = 44.3 * 44.3;
    e.gamma = 7.0;
    const double B = e.c2 * e.rho0 / e.gamma;
    const auto p = [&](double rho) {
      return kind == HealthLimits::Elastic::Kind::tait ? B * (std::pow(rho / e.rho0, 7.0) - 1.0) : e.c2 * (rho - e.rho0);
    };
    CHECK(e.per_mass(1000.0) == Approx(0.0).margin(1e-12));
    for (const double rho : {950.0, 990.0, 1001.0, 1010.0, 1050.0}) {
      CHECK(e.per_mass(rho) > 0.0);
      const double h = 1e-3;  // du/drho = p / rho^2
      CHECK((e.per_mass(rho + h) - e.per_mass(rho - h)) / (2 * h) == Approx(p(rho) / (rho * rho)).epsilon(1e-5));
    }
    e.clamp_negative = true;
    if (kind == HealthLimits::Elastic::Kind::tait) CHECK(e.per_mass(990.0) == 0.0);
  }
  // A non-integer exponent takes the pow branch and agrees with the integral too.
  HealthLimits::Elastic e;
  e.kind = HealthLimits::Elastic::Kind::tait;
  e.rho0 = 1.0;
  e.c2 = 1.0;
  e.gamma = 1.5;
  const double h = 1e-6, rho = 1.02;
  const double B = e.c2 * e.rho0 / e.gamma;
  CHECK((e.per_mass(rho + h) - e.per_mass(rho - h)) / (2 * h) == Approx(B * (std::pow(rho, 1.5) - 1.0) / (rho * rho)).epsilon(1e-5));
}

namespace {

// A 2D tank shaken along x (a wall body with `motion`), optionally with a second, resting wall body.
Config shaken_tank(const std::string& motion, bool resting_post = false) {
  std::string yaml = R"yaml(case: scene
dimension: 2
fluid:
  density: 1000.0
  kinematic_viscosity: 0.0
  eos: {type: tait, sound_speed: 20.0, gamma: 7.0}
  body_force: [0.0, -9.81]
scene:
  domain: {lo: [-0.12, -0.08], hi: [0.72, 0.4], boundaries: [open, open]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [0.6, 0.12]}
      pressure: hydrostatic
  walls:
    - name: tank
      shape:
        type: difference
        shapes:
          - {type: box, lo: [-0.08, -0.08], hi: [0.68, 0.36]}
          - {type: box, lo: [0, 0], hi: [0.6, 0.32]}
      motion: MOTION
)yaml";
  yaml.replace(yaml.find("MOTION"), 6, motion);
  if (resting_post) yaml += "    - name: post\n      shape: {type: box, lo: [0.28, 0.2], hi: [0.32, 0.28]}\n";
  yaml += "discretization: {spacing: 0.04, density: continuity, viscosity: none, wall_pressure: extrapolated, wall_model: prescribed}\n"
          "time: {t_end: 1.0, integrator: leapfrog}\noutput: {times: [1.0], plots: false, profiles: false}\n";
  return load_config_string(yaml);
}

}  // namespace

TEST_CASE("health limits: walls that all share one translation measure the energy in their frame", "[health][motion]") {
  const std::string oscillation = "{type: oscillation, amplitude: [0.01, 0.0], frequency: 0.85, phase: 0.3}";
  {
    const Config c = shaken_tank(oscillation);
    auto cs = make_case<2>(c);
    auto sys = cs->build(c);
    std::vector<double> y0 = sys->initial_state(), ydot(y0.size());
    sys->rhs(0.0, y0.data(), ydot.data());
    const HealthLimits lim = health_limits<2>(c, cs->velocity_scale(c), cs->free_surface(), *sys, y0.data());
    REQUIRE(lim.frame.on);
    const double w = 2 * M_PI * 0.85, t = 0.4;
    CHECK(lim.frame.V(0, t) == Approx(0.01 * w * std::cos(w * t + 0.3)));
    CHECK(lim.frame.A(0, t) == Approx(-0.01 * w * w * std::sin(w * t + 0.3)));
    CHECK(lim.frame.V(1, t) == 0.0);
    // The fluid at rest moves at -V(0) relative to the tank: that kinetic energy is in the budget,
    // and not the bound M V^2/2 of walls in general.
    const auto& L = sys->layout();
    double M = 0.0;
    for (std::size_t i = 0; i < L.n; ++i) M += sys->particles().mass[i];
    const double ke_frame0 = 0.5 * M * lim.frame.V(0, 0.0) * lim.frame.V(0, 0.0);
    CHECK(lim.energy_budget > ke_frame0);
    // Moving with the tank, whatever the tank's speed, is no energy at all in its frame; moving
    // relative to it with more energy than the budget allows is a blow-up named in its frame.
    HealthCheck<2> check(*sys, y0.data(), 0.0, lim);
    const double tc = 1e-3;  // cause_of checks at this time
    const double u_over = std::sqrt(2.0 * 2.0 * lim.energy_budget / M);  // 4x the budget
    std::vector<double> y = y0;
    for (std::size_t i = 0; i < L.n; ++i) y[L.velocity(0) + i] = lim.frame.V(0, tc);
    CHECK(cause_of(check, y) == "");
    for (std::size_t i = 0; i < L.n; ++i) y[L.velocity(0) + i] = lim.frame.V(0, tc) + u_over;
    const std::string cause = cause_of(check, y);
    CHECK(cause.rfind("kinetic energy ", 0) == 0);
    CHECK_THAT(cause, Catch::Matchers::Contains("walls' moving frame"));
  }
  {
    // A constant translation is a frame too (with no inertial force).
    const Config c = shaken_tank("{type: translation, velocity: [0.05, 0.0]}");
    auto cs = make_case<2>(c);
    auto sys = cs->build(c);
    const auto y0 = sys->initial_state();
    const HealthLimits lim = health_limits<2>(c, cs->velocity_scale(c), cs->free_surface(), *sys, y0.data());
    REQUIRE(lim.frame.on);
    CHECK(lim.frame.V(0, 3.0) == 0.05);
    CHECK(lim.frame.A(0, 3.0) == 0.0);
  }
  // No common frame: a second body at rest, a rotation, or a stationary oscillation (the particles
  // stay in place and only carry the velocity).
  for (const auto& [motion, post] : std::vector<std::pair<std::string, bool>>{
           {oscillation, true},
           {"{type: rotation, centre: [0.3, 0.14], angular_velocity: 0.1}", false},
           {"{type: oscillation, amplitude: [0.01, 0.0], frequency: 0.85, stationary: true}", false}}) {
    INFO(motion << (post ? " with a resting body" : ""));
    const Config c = shaken_tank(motion, post);
    auto cs = make_case<2>(c);
    auto sys = cs->build(c);
    const auto y0 = sys->initial_state();
    const HealthLimits lim = health_limits<2>(c, cs->velocity_scale(c), cs->free_surface(), *sys, y0.data());
    CHECK_FALSE(lim.frame.on);
  }
}

TEST_CASE("health check: the last good state is the latest state that passed, on 1 and 2 threads", "[health][threads]") {
  // The check copies each state before it knows whether the state passes, and keeps the copy only
  // when it does: a state that fails must leave the previous good one in place.
  const Evaluated e(shipped("taylor_green", {"discretization.particles_across=16"}));
  const auto& sys = e.sys;
  const auto& y0 = e.y0;
  const HealthLimits& lim = e.lim;
  const auto& L = sys->layout();
  for (const int threads : {1, 2}) {
    INFO("threads " << threads);
    omp_set_num_threads(threads);
    HealthCheck<2> check(*sys, y0.data(), 0.0, lim);
    std::vector<double> y1 = y0, y2 = y0;
    for (std::size_t i = 0; i < L.n; ++i) {
      y1[L.velocity(0) + i] *= 0.99;
      y2[L.velocity(0) + i] *= 0.98;
    }
    check(1e-3, y1.data(), 1e-3);
    check(2e-3, y2.data(), 1e-3);
    CHECK(check.last_good_state() == y2);
    CHECK(check.last_good_time() == 2e-3);
    std::vector<double> bad = y2;
    bad[L.velocity(1) + 3] = std::nan("");
    CHECK_THROWS_AS(check(3e-3, bad.data(), 1e-3), BlowUp);
    CHECK(check.last_good_state() == y2);
    CHECK(check.last_good_time() == 2e-3);
    std::vector<double> fast = y2;  // finite but beyond the speed bound: fails after the copy was made
    fast[L.velocity(0) + 5] = 2.0 * lim.max_speed;
    CHECK_THROWS_AS(check(3e-3, fast.data(), 1e-3), BlowUp);
    CHECK(check.last_good_state() == y2);
    check(3e-3, y1.data(), 1e-3);
    CHECK(check.last_good_state() == y1);
    CHECK(check.last_good_time() == 3e-3);
  }
  omp_set_num_threads(1);
}

TEST_CASE("health check: the energy sums over blocks of particles give the same message on 1, 2 and 3 threads",
          "[health][threads]") {
  // The dam break at dp = 0.04: 1,250 fluid particles, three blocks of the sums (HealthCheck::kSumBlock),
  // Tait elastic energy. Every particle at 3 m/s: far more kinetic energy than the column's budget.
  const Evaluated e(shipped("dam_break", {"discretization.spacing=0.04"}));
  const auto& sys = e.sys;
  const auto& y0 = e.y0;
  const auto& L = sys->layout();
  REQUIRE(L.n > 2 * 512);
  std::vector<double> y = y0;
  for (std::size_t i = 0; i < L.n; ++i) y[L.velocity(0) + i] = 3.0 * std::sin(0.1 * static_cast<double>(i));
  std::vector<std::string> causes;
  for (const int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    HealthCheck<2> check(*sys, y0.data(), 0.0, e.lim);
    CHECK(cause_of(check, y0) == "");
    causes.push_back(cause_of(check, y));
  }
  omp_set_num_threads(1);
  INFO(causes[0]);
  CHECK(causes[0].rfind("kinetic energy ", 0) == 0);
  CHECK(causes[1] == causes[0]);
  CHECK(causes[2] == causes[0]);
}

TEST_CASE("health limits: the elastic energy of a block of particles is per_mass's bit for bit", "[health]") {
  // per_mass_block (the health check's vectorised form) against per_mass for each particle: Tait
  // with whole exponents (1, 2, 7) and a fractional one, clamped or not, linear; densities below,
  // at and above rho0, zero, negative and NaN; with and without each particle's own rest density.
  std::vector<double> rho, own;
  for (int k = 0; k < 203; ++k) {  // not a multiple of the block's runs
    rho.push_back(1000.0 * (0.9 + 0.2 * std::sin(0.37 * k)));
    own.push_back(k % 3 == 0 ? 0.0 : 900.0 + 0.5 * k);
  }
  rho[3] = 0.0;
  rho[17] = -5.0;
  rho[40] = std::nan("");
  rho[41] = 1000.0;
  for (const auto kind : {HealthLimits::Elastic::Kind::tait, HealthLimits::Elastic::Kind::linear}) {
    for (const double gamma : {7.0, 2.0, 1.0, 1.5}) {
      for (const bool clamp : {false, true}) {
        HealthLimits::Elastic e;
        e.kind = kind;
        e.rho0 = 1000.0;
        e.c2 = 88.6 * 88.6;
        e.gamma = gamma;
        e.clamp_negative = clamp;
        for (const bool with_own : {false, true}) {
          INFO("kind " << static_cast<int>(kind) << " gamma " << gamma << " clamp " << clamp << " own " << with_own);
          std::vector<double> got(rho.size(), -1.0);
          e.per_mass_block(rho.data(), with_own ? own.data() : nullptr, static_cast<long>(rho.size()), got.data());
          for (std::size_t i = 0; i < rho.size(); ++i) {
            const double want = e.per_mass(rho[i], with_own ? own[i] : 0.0);
            INFO("particle " << i << " rho " << rho[i]);
            CHECK(std::memcmp(&got[i], &want, sizeof(double)) == 0);
          }
        }
      }
    }
  }
}

TEST_CASE("health check: the scan finds each failure it tests, with its cause, on 1, 2 and 3 threads", "[health][threads]") {
  // The dam break at dp = 0.04 (1,250 fluid particles, three blocks of the scan): a state that
  // passes, then one fault at a time in a particle of the middle block: NaN or Inf in a position, a
  // velocity and the density field, a particle beyond a face closed to outflow, a density <= 0. A
  // particle beyond a face open to outflow is no failure but an exit, which the check notes
  // (run/outflow.hpp).
  const Evaluated e(shipped("dam_break", {"discretization.spacing=0.04"}));
  const auto& sys = e.sys;
  const auto& y0 = e.y0;
  const auto& L = sys->layout();
  REQUIRE(L.has_density);
  const std::size_t p = 700;
  REQUIRE(p < L.n);
  const double inf = std::numeric_limits<double>::infinity();
  struct Fault {
    std::size_t at;
    double value;
    std::string cause;
  };
  const std::vector<Fault> faults = {
      {L.position(0) + p, std::nan(""), "NaN/Inf in the position (component 0)"},
      {L.position(1) + p, -inf, "NaN/Inf in the position (component 1)"},
      {L.velocity(0) + p, inf, "NaN/Inf in the velocity (component 0)"},
      {L.velocity(1) + p, std::nan(""), "NaN/Inf in the velocity (component 1)"},
      {L.density() + p, std::nan(""), "NaN/Inf in a state field"},
      // Below the floor: a face closed to outflow (the dam break's floor), so through a wall.
      {L.position(1) + p, sys->domain().lo[1] - 0.5, "particle left the domain in direction 1 through a face closed to outflow"},
  };
  // Beyond the dam break's open faces (a side, the top): exits, not failures.
  REQUIRE(sys->domain().outflow[0][1]);
  REQUIRE(sys->domain().outflow[1][1]);
  const std::vector<std::pair<std::size_t, double>> exits = {{L.position(0) + p, sys->domain().hi[0] + 0.5},
                                                             {L.position(1) + p, sys->domain().hi[1] + 0.5}};
  for (const int threads : {1, 2, 3}) {
    INFO("threads " << threads);
    omp_set_num_threads(threads);
    HealthCheck<2> check(*sys, y0.data(), 0.0, e.lim);
    CHECK(cause_of(check, y0) == "");
    for (const Fault& f : faults) {
      INFO("expected " << f.cause);
      std::vector<double> y = y0;
      y[f.at] = f.value;
      const std::string cause = cause_of(check, y);
      CHECK(cause.rfind(f.cause, 0) == 0);
    }
    for (const auto& [at, value] : exits) {
      CHECK(cause_of(check, y0) == "");
      CHECK_FALSE(check.exits());
      std::vector<double> y = y0;
      y[at] = value;
      CHECK(cause_of(check, y) == "");
      CHECK(check.exits());
    }
  }
  // A density <= 0 in the latest evaluation (the workspace density the scan reads).
  std::vector<double> y = y0, ydot(y0.size());
  y[L.density() + p] = -1.0;
  sys->rhs(0.0, y.data(), ydot.data());
  for (const int threads : {1, 2, 3}) {
    INFO("threads " << threads);
    omp_set_num_threads(threads);
    HealthCheck<2> check(*sys, y0.data(), 0.0, e.lim);
    CHECK(cause_of(check, y).rfind("density <= 0", 0) == 0);
  }
  omp_set_num_threads(1);
}
