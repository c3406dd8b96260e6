// Bad configs: each error names the file, the line, the full key path and what is wrong.
// Line numbers refer to config_test::base (see config_test_base.hpp).
#include <catch2/catch.hpp>

#include "config_test_base.hpp"
#include "sphmol/config/config.hpp"

using namespace sphmol;
using config_test::base;
using config_test::error_of;
using config_test::with;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("config errors: the base fixture itself is valid", "[config]") {
  CHECK(error_of(base) == "<no error>");
}

TEST_CASE("config errors: unknown keys, with did-you-mean", "[config]") {
  CHECK(error_of(with("  density: 1000", "  densty: 1000")) ==
        "case.yaml:4: fluid.densty: unknown key (did you mean 'density'? allowed in fluid: density, "
        "kinematic_viscosity, eos, body_force, body_force_ramp)");
  CHECK_THAT(error_of(with("output:", "ouptut:")),
             StartsWith("case.yaml:16: ouptut: unknown key (did you mean 'output'?"));
  CHECK_THAT(error_of(with("  t_end: 0.5", "  t_end: 0.5\n  cfl:\n    acustic: 0.2")),
             StartsWith("case.yaml:17: time.cfl.acustic: unknown key (did you mean 'acoustic'?"));
  // '-' for '_' is a close match too.
  CHECK_THAT(error_of(with("  kinematic_viscosity", "  kinematic-viscosity")),
             StartsWith("case.yaml:5: fluid.kinematic-viscosity: unknown key (did you mean 'kinematic_viscosity'?"));
  // Nothing close: no guess, but the allowed keys.
  CHECK(error_of(with("  t_end: 0.5", "  t_end: 0.5\n  banana: 1")) ==
        "case.yaml:16: time.banana: unknown key (allowed in time: t_end, integrator, table, rtol, atol, "
        "cfl, dt, max_steps, krylov)");
  // An unknown key is reported before the "missing" error its typo causes.
  CHECK_THAT(error_of(with("    sound_speed: 0.01", "    soundspeed: 0.01")),
             StartsWith("case.yaml:7: fluid.eos.soundspeed: unknown key (did you mean 'sound_speed'?"));
  CHECK(error_of(with("  density: 1000", "  density: 1000\n  density: 2")) ==
        "case.yaml:5: fluid.density: given twice (first on line 4)");
}

TEST_CASE("config errors: wrong types", "[config]") {
  CHECK(error_of(with("density: 1000", "density: heavy")) ==
        "case.yaml:4: fluid.density: expected a number, got 'heavy'");
  CHECK(error_of(with("density: 1000", "density: \"1000\"")) ==
        "case.yaml:4: fluid.density: expected a number, got the string \"1000\"");
  CHECK(error_of(with("t_end: 0.5", "t_end: true")) == "case.yaml:15: time.t_end: expected a number, got 'true'");
  CHECK(error_of(with("t_end: 0.5", "t_end: .inf")) ==
        "case.yaml:15: time.t_end: expected a finite number, got '.inf'");
  CHECK(error_of(with("t_end: 0.5", "t_end:")) == "case.yaml:15: time.t_end: expected a number, got nothing");
  CHECK(error_of(with("times: [0.1, 0.2]", "times: {first: 0.1}")) ==
        "case.yaml:17: output.times: expected a list of numbers such as [0.1, 0.2], got a map");
  CHECK(error_of(with("times: [0.1, 0.2]", "times: [0.1, soon]")) ==
        "case.yaml:17: output.times[1]: expected a finite number, got 'soon'");
  CHECK(error_of(with("particles_across: 20", "particles_across: 20.5")) ==
        "case.yaml:13: discretization.particles_across: expected an integer, got '20.5'");
  CHECK(error_of(with("dimension: 2", "dimension: [2]")) == "case.yaml:2: dimension: expected an integer, got a list");
  CHECK(error_of(with("times: [0.1, 0.2]", "times: [0.1, 0.2]\n  profiles: maybe")) ==
        "case.yaml:18: output.profiles: expected true or false, got 'maybe'");
  CHECK(error_of(with("case: couette", "case: {name: couette}")) == "case.yaml:1: case: expected a string, got a map");
  CHECK(error_of(with("geometry:\n  channel_height: 1.0e-3\n  channel_length: 5.0e-4\n  wall_velocity: 1.25e-5\n",
                      "geometry: [1, 2]\n\n\n\n")) ==
        "case.yaml:8: geometry: expected a map of keys (channel_height, channel_length, wall_velocity), got a list");
  CHECK(error_of("- 1\n- 2\n") ==
        "case.yaml:1: the config: expected a map of keys (case, dimension, fluid, discretization, "
        "time, output, health, probes, geometry, shock_tube, scene), got a list");
}

TEST_CASE("config errors: missing required values point at the parent section", "[config]") {
  CHECK(error_of(with("  density: 1000\n", "")) ==
        "case.yaml:3: fluid.density: required value missing in section 'fluid' (reference density rho0 "
        "in kg/m^3, > 0)");
  // couette derives c = 10 U from its wall speed; cases without a velocity scale: test_config_sound_speed.cpp.
  CHECK(error_of(with("    sound_speed: 0.01", "    type: linear")) == "<no error>");
  CHECK(error_of(with("case: couette\n", "")) ==
        "case.yaml:1: case: required value missing (one of: couette, poiseuille, taylor_green, hydrostatic, cavity, shock_tube, dam_break, duct, beltrami, scene)");
  CHECK_THAT(error_of(with("  channel_length: 5.0e-4\n", "")),
             StartsWith("case.yaml:8: geometry.channel_length: required value missing in section 'geometry'"));
  CHECK_THAT(error_of(with("  t_end: 0.5", "  rtol: 1e-7")),
             StartsWith("case.yaml:14: time.t_end: required value missing in section 'time'"));
  CHECK(error_of(with("  particles_across: 20", "  kernel: cubic_spline")) ==
        "case.yaml:12: discretization.particles_across: required value missing in section 'discretization' "
        "(or discretization.spacing: give exactly one of the two)");
  // A whole section missing: the error points at the top of the file.
  CHECK_THAT(error_of(with("time:\n  t_end: 0.5\n", "")),
             StartsWith("case.yaml:1: time.t_end: required value missing in section 'time'"));
  CHECK_THAT(error_of(""), StartsWith("case.yaml:1: case: required value missing"));
}

TEST_CASE("config errors: non-physical and out-of-range values name the allowed range", "[config]") {
  struct Bad {
    const char* from;
    const char* to;
    const char* message;
  };
  const Bad bad[] = {
      {"density: 1000", "density: -1", "case.yaml:4: fluid.density: -1 is out of range (allowed: > 0 kg/m^3)"},
      {"density: 1000", "density: 0", "case.yaml:4: fluid.density: 0 is out of range (allowed: > 0 kg/m^3)"},
      {"kinematic_viscosity: 1.0e-6", "kinematic_viscosity: -1e-6",
       "case.yaml:5: fluid.kinematic_viscosity: -1e-06 is out of range (allowed: >= 0 m^2/s)"},
      {"sound_speed: 0.01", "sound_speed: 0", "case.yaml:7: fluid.eos.sound_speed: 0 is out of range (allowed: > 0 m/s)"},
      {"channel_height: 1.0e-3", "channel_height: 0",
       "case.yaml:9: geometry.channel_height: 0 is out of range (allowed: > 0 m)"},
      {"channel_length: 5.0e-4", "channel_length: -1",
       "case.yaml:10: geometry.channel_length: -1 is out of range (allowed: > 0 m)"},
      {"particles_across: 20", "particles_across: 0",
       "case.yaml:13: discretization.particles_across: 0 is out of range (allowed: > 0)"},
      {"particles_across: 20", "particles_across: -5",
       "case.yaml:13: discretization.particles_across: -5 is out of range (allowed: > 0)"},
      {"particles_across: 20", "spacing: -0.1", "case.yaml:13: discretization.spacing: -0.1 is out of range (allowed: > 0 m)"},
      {"particles_across: 20", "particles_across: 20\n  spacing: 1e-4",
       "case.yaml:14: discretization.spacing: both particles_across and spacing are given (allowed: exactly one of them)"},
      {"particles_across: 20", "particles_across: 20\n  smoothing_ratio: 0",
       "case.yaml:14: discretization.smoothing_ratio: 0 is out of range (allowed: > 0 (h / dx))"},
      // The default cubic spline reaches 2 h: h = 0.5 dx touches the nearest particle with W = 0.
      {"particles_across: 20", "particles_across: 20\n  smoothing_ratio: 0.5",
       "case.yaml:14: discretization.smoothing_ratio: 0.5 gives cubic_spline a support of 1 spacings, which does not reach the "
       "nearest particle one spacing away; it needs h / dx > 0.5"},
      {"particles_across: 20", "particles_across: 20\n  xsph: 1.5",
       "case.yaml:14: discretization.xsph: 1.5 is out of range (allowed: [0, 1]; 0 = off)"},
      {"particles_across: 20", "particles_across: 20\n  xsph: -0.1",
       "case.yaml:14: discretization.xsph: -0.1 is out of range (allowed: [0, 1]; 0 = off)"},
      {"particles_across: 20", "particles_across: 20\n  position_noise: 0.3",
       "case.yaml:14: discretization.position_noise: 0.3 is out of range (allowed: [0, 0.25] particle spacings; 0 = off)"},
      {"particles_across: 20", "particles_across: 20\n  position_noise: 0.01",
       "case.yaml:14: discretization.position_noise: is not applied by case 'couette' (its scene is built without noise)"},
      {"particles_across: 20", "particles_across: 20\n  transport_velocity: {step_factor: 0}",
       "case.yaml:14: discretization.transport_velocity.step_factor: 0 is out of range (allowed: > 0 (tau = step_factor h / c))"},
      {"particles_across: 20", "particles_across: 20\n  skin: -0.1",
       "case.yaml:14: discretization.skin: -0.1 is out of range (allowed: >= 0 (in units of h))"},
      {"particles_across: 20", "particles_across: 20\n  wall_layers: -1",
       "case.yaml:14: discretization.wall_layers: -1 is out of range (allowed: >= 0; 0 = fill the kernel support)"},
      {"t_end: 0.5", "t_end: 0", "case.yaml:15: time.t_end: 0 is out of range (allowed: > 0 s)"},
      {"t_end: 0.5", "t_end: 0.5\n  rtol: 0", "case.yaml:16: time.rtol: 0 is out of range (allowed: >= 1e-15, the double round-off)"},
      {"t_end: 0.5", "t_end: 0.5\n  atol: -1e-9", "case.yaml:16: time.atol: -1e-09 is out of range (allowed: > 0)"},
      {"t_end: 0.5", "t_end: 0.5\n  cfl:\n    acoustic: 1.5",
       "case.yaml:17: time.cfl.acoustic: 1.5 is out of range (allowed: (0, 1]: a sound wave may cross at most one smoothing length per step (Monaghan 1992 uses 0.25-0.4))"},
      {"t_end: 0.5", "t_end: 0.5\n  cfl:\n    force: 0", "case.yaml:17: time.cfl.force: 0 is out of range (allowed: (0, 1]: the leapfrog is stable for omega dt < 2 with omega^2 ~ |a|/h; 1 keeps a factor 2 (Monaghan 1992 uses 0.25))"},
      {"t_end: 0.5", "t_end: 0.5\n  cfl:\n    force: 1.01",
       "case.yaml:17: time.cfl.force: 1.01 is out of range (allowed: (0, 1]: the leapfrog is stable for omega dt < 2 with omega^2 ~ |a|/h; 1 keeps a factor 2 (Monaghan 1992 uses 0.25))"},
      {"t_end: 0.5", "t_end: 0.5\n  cfl:\n    viscous: 0", "case.yaml:17: time.cfl.viscous: 0 is out of range (allowed: (0, 0.125]: the explicit viscous step limit dt <= 0.125 h^2/nu of Morris, Fox & Zhu 1997; the leapfrog Couette flow diverges at 0.15)"},
      {"t_end: 0.5", "t_end: 0.5\n  dt: 0", "case.yaml:16: time.dt: 0 is out of range (allowed: > 0 s)"},
      {"t_end: 0.5", "t_end: 0.5\n  max_steps: 0", "case.yaml:16: time.max_steps: 0 is out of range (allowed: > 0)"},
      {"kinematic_viscosity: 1.0e-6", "kinematic_viscosity: 1.0e-6\n  body_force: [1, 0, 0]",
       "case.yaml:6: fluid.body_force: has 3 components, expected 2 (one per dimension)"},
      {"dimension: 2", "dimension: 4", "case.yaml:2: dimension: 4 is out of range (allowed: 1, 2 or 3)"},
      // The files of an output time are named by six significant digits.
      {"times: [0.1, 0.2]", "times: [0.1, 0.10000001]",
       "case.yaml:17: output.times: the output times 0.1 and 0.10000001 name the same files (t0.1): output times must differ in "
       "their first six significant digits"},
      {"times: [0.1, 0.2]", "times: [0.1, -0.2]", "case.yaml:17: output.times[1]: -0.2 is out of range (allowed: > 0 s)"},
      {"times: [0.1, 0.2]", "times: [0, 0.2]", "case.yaml:17: output.times[0]: 0 is out of range (allowed: > 0 s)"},
      {"times: [0.1, 0.2]", "times:\n    - 0.2\n    - 0.1",
       "case.yaml:19: output.times[1]: 0.1 is not after the previous time 0.2 (times must be strictly increasing)"},
  };
  for (const auto& b : bad) {
    INFO(b.to);
    CHECK(error_of(with(b.from, b.to)) == b.message);
  }
  // The viscous CFL coefficient is bounded by the explicit viscous limit.
  CHECK(error_of(with("t_end: 0.5", "t_end: 0.5\n  cfl:\n    viscous: 2")) == "case.yaml:17: time.cfl.viscous: 2 is out of range " "(allowed: (0, 0.125]: the explicit viscous step limit dt <= 0.125 h^2/nu of Morris, Fox & Zhu 1997; the leapfrog Couette flow diverges at 0.15)");
  CHECK(error_of(with("t_end: 0.5", "t_end: 0.5\n  cfl:\n    viscous: 0.125")) == "<no error>");
}

TEST_CASE("config errors: enumerations list the allowed values", "[config]") {
  CHECK(error_of(with("case: couette", "case: couete")) ==
        "case.yaml:1: case: unknown value 'couete' (did you mean 'couette'? allowed: couette, poiseuille, taylor_green, hydrostatic, cavity, shock_tube, dam_break, duct, beltrami, scene)");
  CHECK(error_of(with("particles_across: 20", "particles_across: 20\n  viscosity: mooris")) ==
        "case.yaml:14: discretization.viscosity: unknown value 'mooris' (did you mean 'morris'? allowed: "
        "strain_rate, morris, none)");
  CHECK(error_of(with("particles_across: 20", "particles_across: 20\n  kernel: gaussian_bell")) ==
        "case.yaml:14: discretization.kernel: unknown value 'gaussian_bell' (allowed: cubic_spline, lucy, gaussian, truncated_exponential, quartic_liu, quintic_morris, quadratic_johnson, super_gaussian, desbrun_spiky, muller_poly6, composite, wendland_c2)");
  CHECK(error_of(with("sound_speed: 0.01", "sound_speed: 0.01\n    type: tate")) ==
        "case.yaml:8: fluid.eos.type: unknown value 'tate' (did you mean 'tait'? allowed: linear, linear_relative, tait, ideal_gas)");
  CHECK_THAT(error_of(with("particles_across: 20", "particles_across: 20\n  density: contiguity")),
             StartsWith("case.yaml:14: discretization.density: unknown value 'contiguity' (did you mean 'continuity'? allowed: summation, normalised_summation, continuity)"));
  CHECK_THAT(error_of(with("particles_across: 20", "particles_across: 20\n  momentum: asymmetric")),
             StartsWith("case.yaml:14: discretization.momentum: unknown value 'asymmetric' (allowed: symmetric_117, symmetric_116, integral_approach)"));
  CHECK_THAT(error_of(with("particles_across: 20", "particles_across: 20\n  boundary: ghost")),
             StartsWith("case.yaml:14: discretization.boundary: 'ghost' is not available for case 'couette'"));
  CHECK(error_of(with("particles_across: 20", "particles_across: 20\n  neighbor_search: cells")) ==
        "case.yaml:14: discretization.neighbor_search: unknown value 'cells' (allowed: kdtree, cell_list, all_pairs)");
  CHECK(error_of(with("t_end: 0.5", "t_end: 0.5\n  integrator: euler")) ==
        "case.yaml:16: time.integrator: unknown value 'euler' (allowed: arkode_erk, leapfrog, leapfrog_kdk, cvode_adams, leapfrog_imex, arkode_imex)");
}

TEST_CASE("config errors: time.table must be a SUNDIALS explicit table", "[config]") {
  // An implicit (DIRK) table is a real SUNDIALS name, but not an explicit one.
  CHECK_THAT(error_of(with("t_end: 0.5", "t_end: 0.5\n  table: ARKODE_SDIRK_2_1_2")),
             StartsWith("case.yaml:16: time.table: 'ARKODE_SDIRK_2_1_2' is not a SUNDIALS explicit (ERK) Butcher table"));
  CHECK_THAT(error_of(with("t_end: 0.5", "t_end: 0.5\n  table: ARKODE_DORMAND_PRINCE_745")),
             Contains("did you mean 'ARKODE_DORMAND_PRINCE_7_4_5'?"));
  CHECK(error_of(with("t_end: 0.5", "t_end: 0.5\n  table: ARKODE_FEHLBERG_13_7_8")) == "<no error>");
}

TEST_CASE("config errors: the case must fit dimension, walls and body force", "[config]") {
  CHECK(error_of(with("dimension: 2", "dimension: 3")) ==
        "case.yaml:2: dimension: case 'couette' needs dimension 2 (got 3)");
  const std::string poiseuille = with("case: couette", "case: poiseuille");
  CHECK(error_of(poiseuille) ==
        "case.yaml:11: geometry.wall_velocity: must be 0 for case 'poiseuille' (got 1.25e-05; a moving wall is "
        "case 'couette')");
  const std::string resting = with("  wall_velocity: 1.25e-5\n", "", poiseuille);
  CHECK_THAT(error_of(resting),
             StartsWith("case.yaml:3: fluid.body_force: required value missing in section 'fluid' (case "
                        "'poiseuille' needs a nonzero x-component"));
  CHECK_THAT(error_of(with("    sound_speed: 0.01", "    sound_speed: 0.01\n  body_force: [0, 1e-4]", resting)),
             StartsWith("case.yaml:8: fluid.body_force: case 'poiseuille' needs a nonzero x-component"));
  CHECK(error_of(with("    sound_speed: 0.01", "    sound_speed: 0.01\n  body_force: [1e-4, 0]", resting)) ==
        "<no error>");
  CHECK(error_of(with("wall_velocity: 1.25e-5", "wall_velocity: 0")) ==
        "case.yaml:11: geometry.wall_velocity: case 'couette' needs a nonzero top-plate speed v0 in m/s");
  CHECK_THAT(error_of(with("  wall_velocity: 1.25e-5\n", "")),
             StartsWith("case.yaml:8: geometry.wall_velocity: required value missing in section 'geometry' (case "
                        "'couette' needs a nonzero top-plate speed"));
}

TEST_CASE("config errors: YAML syntax and missing files", "[config]") {
  CHECK_THAT(error_of(with("times: [0.1, 0.2]", "times: [0.1, 0.2")), StartsWith("case.yaml:1"));
  CHECK_THAT(error_of(with("times: [0.1, 0.2]", "times: [0.1, 0.2")), Contains(": YAML syntax error: "));
  CHECK_THAT(error_of(with("  density: 1000", "  density: 1000\n density: 3")),
             StartsWith("case.yaml:5: YAML syntax error: "));
  try {
    (void)load_config("/nonexistent/dir/run.yaml");
    FAIL("no error for a missing file");
  } catch (const ConfigError& e) {
    CHECK(std::string(e.what()) == "/nonexistent/dir/run.yaml: cannot open config file: No such file or directory");
  }
}
