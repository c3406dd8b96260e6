// What the scene builders and the assembly reject is rejected by the loader first, with the key and
// its location (config/scene_checks.cpp); sizes, step counts and CFL coefficients are bounded there.
#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/config/scene_checks.hpp"
#include "sphmol/cases/case_module.hpp"

using namespace sphmol;

namespace {

std::string shipped(const std::string& name) { return std::string(SPHMOL_SOURCE_DIR) + "/verification/" + name + ".yaml"; }

std::string load_error(const std::string& name, const std::vector<std::string>& overrides) {
  try {
    (void)load_config(shipped(name), overrides);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "<no error>";
}

// Builds the system of an accepted config and evaluates its first right-hand side (where the
// neighbour search checks the periodic lengths); returns the exception text, or "" on success.
std::string build_error(const Config& c) {
  try {
    const auto run = [&](auto cs) {
      auto sys = cs->build(c);
      std::vector<double> y = sys->initial_state(), ydot(y.size());
      sys->rhs(0.0, y.data(), ydot.data());
    };
    if (c.dimension == 1) run(make_case<1>(c));
    else if (c.dimension == 2) run(make_case<2>(c));
    else run(make_case<3>(c));
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("scene checks: inputs the scene or the assembly used to reject at run time are config errors", "[config][scene]") {
  // Each of these loaded and then failed in the scene builder or the assembly ("run failed", exit 1).
  CHECK(load_error("dam_break", {"fluid.body_force=[0, 0]"}) ==
        "--set fluid.body_force=[0, 0]: fluid.body_force: case 'dam_break' needs gravity along the last axis, pointing down, e.g. body_force: [0, -9.81]");
  CHECK(load_error("dam_break", {"discretization.wall_pressure=rest", "discretization.boundary=ghost"}) ==
        "--set discretization.boundary=ghost: discretization.boundary: 'ghost' is not available for case 'dam_break': the tank "
        "is built from wall particles (allowed: wall_particles)");
  CHECK(load_error("hydrostatic", {"fluid.body_force=[0.5, -9.81]"}).find("fluid.body_force: case 'hydrostatic' needs gravity") !=
        std::string::npos);
  CHECK(load_error("dam_break", {"fluid.eos={type: linear, sound_speed: 88.6}"}).find("fluid.eos: case 'dam_break' needs eos.type 'tait' or 'linear_relative'") !=
        std::string::npos);
  CHECK(load_error("taylor_green", {"geometry.box=[1, 0.5]"}).find("geometry.box[1]: 0.5 differs from box[0] = 1") != std::string::npos);
  CHECK(load_error("cavity", {"discretization.boundary=virtual_repulsive", "discretization.wall_model=prescribed", "discretization.repulsive={strength: 1}"})
            .find("discretization.boundary: 'virtual_repulsive' is not available for case 'cavity': virtual_repulsive walls exert no shear") != std::string::npos);
  CHECK(load_error("taylor_green", {"fluid.kinematic_viscosity=0", "discretization.energy=true"}).find("discretization.energy: case 'taylor_green' provides no initial") !=
        std::string::npos);
  CHECK(load_error("cavity", {"discretization.pair_passes=fused", "discretization.viscosity=strain_rate"})
            .find("discretization.pair_passes: 'fused' is not available with viscosity: strain_rate") != std::string::npos);
  CHECK(load_error("shock_tube_virtual", {"discretization.repulsive.r0=3"})
            .find("discretization.repulsive: r0 = 3 spacings must lie inside the kernel support (3 spacings") != std::string::npos);
  CHECK(load_error("shock_tube_1d", {"shock_tube.right.velocity=12"}).find(": shock_tube: the states separate into a vacuum") !=
        std::string::npos);
  // Whole numbers of the spacing, named by the length that is not one.
  CHECK(load_error("couette", {"geometry.channel_length=0.51e-3"}).find("geometry.channel_length: geometry.channel_length (0.00051 m) is not a "
                                                                       "whole number of the particle spacing 2.5e-05 m") != std::string::npos);
  CHECK(load_error("dam_break", {"discretization.spacing=0.03"}).find("geometry.column[0] (1 m) is not a whole number") != std::string::npos);
}

TEST_CASE("scene checks: every shipped case loads as it is", "[config][scene]") {
  for (const char* name : {"couette", "poiseuille", "taylor_green", "cavity", "hydrostatic", "dam_break", "shock_tube",
                           "shock_tube_1d", "shock_tube_virtual"}) {
    INFO(name);
    CHECK(load_error(name, {}) == "<no error>");
  }
}

TEST_CASE("scene checks: a periodic length shorter than two neighbour radii names the length and its line", "[config][scene]") {
  // 10 particles across: dx = 1e-4 m, h = 1.3e-4 m, radius (2 + 0.3) h = 3e-4 m > half of 5e-4 m.
  const std::string e = load_error("couette", {"discretization.particles_across=10"});
  INFO(e);
  CHECK(e.rfind(shipped("couette") + ":", 0) == 0);  // FILE:LINE of channel_length in the file
  CHECK(e.find(": geometry.channel_length: the periodic length 0.0005 m is shorter than two neighbour radii (2 x 0.000299 m") !=
        std::string::npos);
  CHECK(load_error("couette", {"discretization.particles_across=20"}) == "<no error>");
  CHECK(load_error("taylor_green", {"discretization.particles_across=4"}).find("geometry.box: the periodic length 1 m is shorter") !=
        std::string::npos);
}

TEST_CASE("scene checks: ghost walls facing each other closer than the support less a spacing are refused", "[config][scene][ghost]") {
  // The generator makes no images of images (through one wall, then the other); they lie gap + dx from
  // the fluid. A 2D tube two spacings wide (Gaussian, h = 1.3 dx: support 3.9 dx) loaded and blew up
  // at t = 0.049 s ("density <= 0"); three spacings (gap + dx = 4 dx) give the errors of five.
  const std::vector<std::string> tube = {"discretization.spacing=0.005", "time.t_end=0.05", "output.times=[0.05]"};
  const auto with = [&](std::vector<std::string> o, const std::string& extra) {
    o.push_back(extra);
    return o;
  };
  const std::string e = load_error("shock_tube", with(tube, "geometry.tube_width=0.01"));
  INFO(e);
  CHECK(e.find(": geometry.tube_width: ghost walls facing each other 0.01 m apart: the images of images through both walls, which "
               "the ghost boundary does not make, would lie within the kernel support of the fluid (gap + dx = 0.015 m < support "
               "0.0195 m). Widen the gap to at least 3 spacings (0.015 m), or use discretization.boundary: wall_particles") !=
        std::string::npos);
  CHECK(load_error("shock_tube", with(tube, "geometry.tube_width=0.015")) == "<no error>");
  // With wall particles the width is periodic, with its own bound.
  CHECK(load_error("shock_tube", with(with(tube, "geometry.tube_width=0.015"), "discretization.boundary=wall_particles"))
            .find("the periodic length") != std::string::npos);
  // The box cases: the cavity (Wendland C2 at h = 2 dx: support 4 dx) and the hydrostatic tank.
  CHECK(load_error("cavity", {"discretization.boundary=ghost", "discretization.wall_model=prescribed", "discretization.particles_across=2"})
            .find("geometry.box: ghost walls facing each other 1 m apart") != std::string::npos);
  CHECK(load_error("cavity", {"discretization.boundary=ghost", "discretization.wall_model=prescribed", "discretization.particles_across=3"}) == "<no error>");
  CHECK(load_error("hydrostatic", {"discretization.boundary=ghost", "discretization.wall_pressure=rest", "geometry.box=[0.05, 0.9]"})
            .find("geometry.box: ghost walls facing each other 0.05 m apart") != std::string::npos);
  CHECK(load_error("hydrostatic", {"discretization.boundary=ghost", "discretization.wall_pressure=rest", "geometry.box=[0.075, 0.9]"}) ==
        "<no error>");
}

TEST_CASE("scene checks: an inviscid channel is a config error, not a false blow-up", "[config][scene]") {
  // nu = 0 used to load and then end as "fluid particle inside a wall": the reference series threw
  // for nu = 0 and the measurement took that for a particle outside the channel.
  for (const char* name : {"couette", "poiseuille"}) {
    INFO(name);
    const std::string e = load_error(name, {"fluid.kinematic_viscosity=0"});
    CHECK(e.find("--set fluid.kinematic_viscosity=0: fluid.kinematic_viscosity: case '" + std::string(name) +
                 "' is driven by viscosity and measured against the viscous start-up series; it needs nu > 0 (got 0)") !=
          std::string::npos);
  }
}

TEST_CASE("scene checks: absurd sizes are refused before allocation with the estimate and the limit", "[config][scene]") {
  const std::string e = load_error("couette", {"discretization.particles_across=1000000000"});
  INFO(e);
  CHECK(e.find("--set discretization.particles_across=1000000000: discretization.particles_across: the run needs about ") == 0);
  CHECK(e.find(" GB (5e+17 fluid + ") != std::string::npos);
  CHECK(e.find("GB of memory") != std::string::npos);
  CHECK(load_error("dam_break", {}) == "<no error>");  // 21,000 particles: far below any machine
  CHECK(physical_memory_bytes() > 1e8);
}

TEST_CASE("scene checks: over MPI ranks the memory check asks this machine for its ranks' shares", "[config][scene]") {
  // The 3D dam break at 2 mm: about 6.5e7 particles by the scene's bound, hundreds of GB as one
  // process. Split over many ranks on many machines each machine holds its ranks' shares; with all
  // the ranks on this machine it holds the whole scene again.
  const std::string file = std::string(SPHMOL_SOURCE_DIR) + "/examples/dam_break_3d.yaml";
  const std::vector<std::string> fine = {"discretization.spacing=0.002", "probes=[]"};
  const auto error = [&] {
    try {
      (void)load_config(file, fine);
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("<no error>");
  };
  struct Restore {
    ~Restore() { set_ranks_on_machine({}); }
  } restore;
  const std::string serial = error();
  INFO(serial);
  CHECK(serial.find("the run needs about ") != std::string::npos);
  CHECK(serial.find("MPI ranks") == std::string::npos);
  set_ranks_on_machine({1 << 20, 1});  // one of a million ranks here
  CHECK(error() == "<no error>");
  set_ranks_on_machine({1 << 20, 1 << 20});  // all of them here
  const std::string all_here = error();
  CHECK(all_here.find("of it on this machine (1048576 of the run's 1048576 MPI ranks), more than this machine's ") != std::string::npos);
  CHECK_THROWS_AS(set_ranks_on_machine({2, 3}), std::invalid_argument);
  CHECK_THROWS_AS(set_ranks_on_machine({0, 0}), std::invalid_argument);
}

TEST_CASE("scene checks: step and checkpoint counts beyond time.max_steps are refused up front", "[config][scene]") {
  const std::string fixed = load_error("cavity", {"time.max_steps=1000"});
  CHECK(fixed.rfind(shipped("cavity") + ":", 0) == 0);  // the line of time.dt in the file
  CHECK(fixed.find(": time.dt: t_end / dt = 20 / 0.001 = 20000 steps, more than time.max_steps = 1000") != std::string::npos);
  const std::string cfl = load_error("dam_break", {"time.max_steps=1000"});
  CHECK(cfl.find("--set time.max_steps=1000: time.max_steps: 1000 steps cannot reach time.t_end = 1 s: the CFL step is at most ") == 0);
  const std::string cp = load_error("couette", {"output.checkpoint_every=1e-9"});
  CHECK(cp.find("--set output.checkpoint_every=1e-9: output.checkpoint_every: 1e-09 s gives 1e+09 checkpoints") == 0);
}

TEST_CASE("scene checks: CFL coefficients are bounded by the integrators' stability", "[config][scene]") {
  CHECK(load_error("couette", {"time.cfl.viscous=2"}).find("time.cfl.viscous: 2 is out of range (allowed: (0, 0.125]: the explicit "
                                                           "viscous step limit") != std::string::npos);
  CHECK(load_error("couette", {"time.cfl.viscous=0.125"}) == "<no error>");
  CHECK(load_error("couette", {"time.cfl.acoustic=1.5"}).find("time.cfl.acoustic: 1.5 is out of range (allowed: (0, 1]") != std::string::npos);
  CHECK(load_error("couette", {"time.cfl.force=1.5"}).find("time.cfl.force: 1.5 is out of range (allowed: (0, 1]") != std::string::npos);
}

TEST_CASE("scene checks: every config the loader accepts builds (random search over the shipped cases)", "[config][scene]") {
  // A deterministic random search: each trial takes a shipped case at a small resolution and sets
  // 1-4 keys to values drawn from the list below. A config the loader accepts must build and
  // evaluate its first right-hand side; an error there would be an input error without a key.
  struct Base {
    const char* name;
    std::vector<std::string> small;
  };
  const std::vector<Base> bases = {
      {"couette", {"discretization.particles_across=20"}},
      {"poiseuille", {"discretization.particles_across=20"}},
      {"taylor_green", {"discretization.particles_across=16"}},
      {"cavity", {"discretization.particles_across=12"}},
      {"hydrostatic", {"discretization.particles_across=10"}},
      {"dam_break", {"discretization.spacing=0.1"}},
      {"shock_tube", {"discretization.spacing=0.0125"}},
      {"shock_tube_1d", {"discretization.spacing=0.01"}},
      {"shock_tube_virtual", {"discretization.spacing=0.0125"}},
  };
  const std::vector<std::vector<std::string>> variants = {
      {"fluid.kinematic_viscosity=0", "fluid.kinematic_viscosity=1e-6", "fluid.kinematic_viscosity=0.01"},
      {"fluid.body_force=[0, 0]", "fluid.body_force=[0, -9.81]", "fluid.body_force=[1e-4, 0]", "fluid.body_force=[0, 9.81]",
       "fluid.body_force=[1]"},
      {"fluid.eos.type=linear", "fluid.eos.type=linear_relative", "fluid.eos.type=tait", "fluid.eos.type=ideal_gas"},
      {"fluid.eos.sound_speed=10", "fluid.eos.gamma=1.4"},
      {"discretization.boundary=wall_particles", "discretization.boundary=ghost", "discretization.boundary=virtual_repulsive"},
      {"discretization.density=summation", "discretization.density=normalised_summation", "discretization.density=continuity"},
      {"discretization.particle_mass=gradient", "discretization.particle_mass=summation"},
      {"discretization.viscosity=morris", "discretization.viscosity=strain_rate", "discretization.viscosity=none"},
      {"discretization.pair_passes=fused", "discretization.pair_passes=stored", "discretization.pair_passes=auto"},
      {"discretization.wall_pressure=rest", "discretization.wall_pressure=extrapolated", "discretization.wall_pressure=dynamic"},
      {"discretization.wall_model=prescribed", "discretization.wall_model=morris"},
      {"discretization.smoothing_length=density", "discretization.smoothing_length=ode", "discretization.smoothing_length=constant"},
      {"discretization.energy=true", "discretization.energy=false"},
      {"discretization.smoothing_ratio=1.0", "discretization.smoothing_ratio=2.0", "discretization.smoothing_ratio=4.0"},
      {"discretization.skin=0", "discretization.skin=2"},
      {"discretization.kernel=wendland_c2", "discretization.kernel=gaussian", "discretization.kernel=quintic_morris",
       "discretization.kernel=composite"},
      {"discretization.particles_across=3", "discretization.particles_across=7", "discretization.particles_across=12"},
      {"discretization.spacing=0.05", "discretization.spacing=0.0125", "discretization.spacing=0.03"},
      {"discretization.neighbor_search=cell_list", "discretization.neighbor_search=all_pairs"},
      {"discretization.reorder=true", "discretization.xsph=0.3", "discretization.density_diffusion=0.1"},
      {"discretization.artificial_viscosity={alpha: 1}", "discretization.transport_velocity={}",
       "discretization.position_noise=0.1"},
      {"discretization.repulsive={strength: 1e-3, r0: 1.0}", "discretization.repulsive={strength: 1, r0: 5}"},
      {"discretization.wall_layers=1", "discretization.wall_layers=3", "discretization.wall_slip=free_slip"},
      {"geometry.box=[1, 1]", "geometry.box=[1, 0.5]", "geometry.box=[0.1, 0.1]", "geometry.box=[4, 3]"},
      {"geometry.channel_length=0.1e-3", "geometry.channel_length=0.33e-3", "geometry.channel_length=1e-3"},
      {"geometry.wall_velocity=0", "geometry.wall_velocity=1"},
      {"geometry.column=[1, 2]", "geometry.column=[0.5, 0.5]", "geometry.column=[0.45, 1]"},
      {"geometry.tube_width=0.0125", "geometry.tube_width=0.05", "geometry.tube_length=0.5"},
      {"shock_tube.right.velocity=5", "shock_tube.right.velocity=12", "shock_tube.left.velocity=-12"},
      {"time.integrator=leapfrog", "time.integrator=arkode_erk", "time.integrator=cvode_adams", "time.integrator=leapfrog_kdk"},
      {"dimension=1", "dimension=2"},
  };
  std::mt19937 rng(20260);
  int accepted = 0, rejected = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Base& b = bases[rng() % bases.size()];
    std::vector<std::string> overrides = b.small;
    const int k = 1 + static_cast<int>(rng() % 4);
    for (int j = 0; j < k; ++j) {
      const auto& v = variants[rng() % variants.size()];
      overrides.push_back(v[rng() % v.size()]);
    }
    Config c;
    try {
      c = load_config(shipped(b.name), overrides);
    } catch (const ConfigError&) {
      ++rejected;
      continue;
    }
    ++accepted;
    std::string what = b.name;
    for (const auto& o : overrides) what += " --set " + o;
    INFO(what);
    CHECK(build_error(c) == "");
  }
  INFO("accepted " << accepted << ", rejected " << rejected);
  // The search means something only if both sides are well represented.
  CHECK(accepted >= 80);
  CHECK(rejected >= 80);
}
