// Valid configs: values, defaults, the shipped config/defaults.yaml, output-time resolution,
// and the to_yaml round trip.
#include "sphmol/cases/channel/channel_settings.hpp"
#include <catch2/catch.hpp>

#include "config_test_base.hpp"
#include "sphmol/config/config.hpp"

using namespace sphmol;
using config_test::base;
using config_test::error_of;
using config_test::has_notice;
using config_test::with;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

void require_same(const Config& a, const Config& b) {
  CHECK(a.case_name == b.case_name);
  CHECK(a.dimension == b.dimension);
  CHECK(a.fluid.density == b.fluid.density);
  CHECK(a.fluid.kinematic_viscosity == b.fluid.kinematic_viscosity);
  CHECK(a.fluid.eos.type == b.fluid.eos.type);
  CHECK(a.fluid.eos.sound_speed == b.fluid.eos.sound_speed);
  CHECK(a.fluid.body_force == b.fluid.body_force);
  REQUIRE(a.case_settings);
  REQUIRE(b.case_settings);
  CHECK(a.case_settings->to_yaml() == b.case_settings->to_yaml());
  const auto &da = a.discretization, &db = b.discretization;
  CHECK(da.particles_across == db.particles_across);
  CHECK(da.spacing == db.spacing);
  CHECK(da.kernel == db.kernel);
  CHECK(da.smoothing_ratio == db.smoothing_ratio);
  CHECK(da.density == db.density);
  CHECK(da.momentum == db.momentum);
  CHECK(da.viscosity == db.viscosity);
  CHECK(da.xsph == db.xsph);
  CHECK(da.boundary == db.boundary);
  CHECK(da.wall_layers == db.wall_layers);
  CHECK(da.neighbor_search == db.neighbor_search);
  CHECK(da.skin == db.skin);
  const auto &ta = a.time, &tb = b.time;
  CHECK(ta.t_end == tb.t_end);
  CHECK(ta.integrator == tb.integrator);
  CHECK(ta.table == tb.table);
  CHECK(ta.rtol == tb.rtol);
  CHECK(ta.atol == tb.atol);
  CHECK(ta.cfl.acoustic == tb.cfl.acoustic);
  CHECK(ta.cfl.force == tb.cfl.force);
  CHECK(ta.cfl.viscous == tb.cfl.viscous);
  CHECK(ta.dt == tb.dt);
  CHECK(ta.max_steps == tb.max_steps);
  CHECK(a.output.directory == b.output.directory);
  CHECK(a.output.times == b.output.times);
  CHECK(a.output.profiles == b.output.profiles);
}

}  // namespace

TEST_CASE("config: a valid config loads with its values and the defaults", "[config]") {
  const Config c = load_config_string(base, {}, "case.yaml");
  CHECK(c.source == "case.yaml");
  CHECK(c.case_name == "couette");
  CHECK(c.dimension == 2);
  CHECK(c.fluid.density == 1000.0);
  CHECK(c.fluid.kinematic_viscosity == 1.0e-6);
  CHECK(c.fluid.eos.sound_speed == 0.01);
  CHECK(c.settings<ChannelSettings>().channel_height == 1.0e-3);
  CHECK(c.settings<ChannelSettings>().channel_length == 5.0e-4);
  CHECK(c.settings<ChannelSettings>().wall_velocity == 1.25e-5);
  CHECK(c.discretization.particles_across == 20);
  CHECK(c.time.t_end == 0.5);
  // Defaults, resolved.
  CHECK(c.fluid.eos.type == "linear");
  CHECK(c.fluid.body_force == std::vector<double>{0.0, 0.0});  // one zero per dimension
  CHECK(c.discretization.spacing == 0.0);
  CHECK(c.discretization.kernel == "cubic_spline");
  CHECK(c.discretization.smoothing_ratio == 1.3);
  CHECK(c.discretization.density == "summation");
  CHECK(c.discretization.momentum == "symmetric_117");
  CHECK(c.discretization.viscosity == "morris");
  CHECK(c.discretization.xsph == 0.0);
  CHECK(c.discretization.boundary == "wall_particles");
  CHECK(c.discretization.wall_layers == 0);
  CHECK(c.discretization.neighbor_search == "kdtree");
  CHECK(c.discretization.skin == 0.3);
  CHECK(c.time.integrator == "arkode_erk");
  CHECK(c.time.table == "ARKODE_DORMAND_PRINCE_7_4_5");
  CHECK(c.time.rtol == 1e-6);
  CHECK(c.time.atol == 1e-12);
  CHECK(c.time.cfl.acoustic == 0.25);
  CHECK(c.time.cfl.force == 0.25);
  CHECK(c.time.cfl.viscous == 0.125);
  CHECK_FALSE(c.time.dt.has_value());
  CHECK(c.time.max_steps == 10'000'000);
  CHECK(c.output.directory == "out");
  CHECK(c.output.times == std::vector<double>{0.1, 0.2, 0.5});  // t_end appended
  CHECK(c.output.profiles);
  CHECK(c.notices.empty());
}

TEST_CASE("config: every key given explicitly", "[config]") {
  const std::string yaml = R"(case: poiseuille
dimension: 2
fluid: {density: 998.2, kinematic_viscosity: 1e-6, eos: {type: linear, sound_speed: 3}, body_force: [2e-4, -1]}
geometry: {channel_height: 2, channel_length: 1, wall_velocity: 0}
discretization:
  spacing: 0.05
  kernel: cubic_spline
  smoothing_ratio: 1.5
  density: summation
  momentum: symmetric_117
  viscosity: morris
  xsph: 1
  boundary: wall_particles
  wall_layers: 4
  neighbor_search: all_pairs
  skin: 0
time:
  t_end: 2
  integrator: leapfrog
  table: ARKODE_VERNER_8_5_6
  rtol: 1e-9
  atol: 1e-14
  cfl: {acoustic: 1, force: 0.5, viscous: 0.1}
  dt: 1e-4
  max_steps: 1e7
output: {directory: "res/run 1", times: [2], profiles: no}
)";
  const Config c = load_config_string(yaml);
  CHECK(c.source == "<string>");
  CHECK(c.case_name == "poiseuille");
  CHECK(c.fluid.density == 998.2);
  CHECK(c.fluid.kinematic_viscosity == 1e-6);
  CHECK(c.fluid.eos.sound_speed == 3.0);
  CHECK(c.fluid.body_force == std::vector<double>{2e-4, -1.0});
  CHECK(c.settings<ChannelSettings>().channel_height == 2.0);
  CHECK(c.discretization.particles_across == 0);
  CHECK(c.discretization.spacing == 0.05);
  CHECK(c.discretization.smoothing_ratio == 1.5);
  CHECK(c.discretization.viscosity == "morris");
  CHECK(c.discretization.xsph == 1.0);
  CHECK(c.discretization.wall_layers == 4);
  CHECK(c.discretization.neighbor_search == "all_pairs");
  CHECK(c.discretization.skin == 0.0);
  CHECK(c.time.integrator == "leapfrog");
  CHECK(c.time.table == "ARKODE_VERNER_8_5_6");
  CHECK(c.time.rtol == 1e-9);
  CHECK(c.time.atol == 1e-14);
  CHECK(c.time.cfl.acoustic == 1.0);
  CHECK(c.time.cfl.force == 0.5);
  CHECK(c.time.cfl.viscous == 0.1);
  REQUIRE(c.time.dt.has_value());
  CHECK(*c.time.dt == 1e-4);
  CHECK(c.time.max_steps == 10'000'000);
  CHECK(c.output.directory == "res/run 1");
  CHECK(c.output.times == std::vector<double>{2.0});  // t_end given: not added twice
  CHECK_FALSE(c.output.profiles);
}

TEST_CASE("config: config/defaults.yaml loads and holds the documented defaults", "[config]") {
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/config/defaults.yaml");
  const Config d;  // the defaults of config.hpp
  CHECK(c.case_name == "poiseuille");
  CHECK(c.dimension == d.dimension);
  CHECK(c.fluid.eos.type == d.fluid.eos.type);
  CHECK(c.discretization.kernel == d.discretization.kernel);
  CHECK(c.discretization.smoothing_ratio == d.discretization.smoothing_ratio);
  CHECK(c.discretization.density == d.discretization.density);
  CHECK(c.discretization.momentum == d.discretization.momentum);
  CHECK(c.discretization.viscosity == d.discretization.viscosity);
  CHECK(c.discretization.xsph == d.discretization.xsph);
  CHECK(c.discretization.boundary == d.discretization.boundary);
  CHECK(c.discretization.wall_layers == d.discretization.wall_layers);
  CHECK(c.discretization.neighbor_search == d.discretization.neighbor_search);
  CHECK(c.discretization.skin == d.discretization.skin);
  CHECK(c.time.integrator == d.time.integrator);
  CHECK(c.time.table == d.time.table);
  CHECK(c.time.rtol == d.time.rtol);
  CHECK(c.time.atol == d.time.atol);
  CHECK(c.time.cfl.acoustic == d.time.cfl.acoustic);
  CHECK(c.time.cfl.force == d.time.cfl.force);
  CHECK(c.time.cfl.viscous == d.time.cfl.viscous);
  CHECK(c.time.dt == d.time.dt);
  CHECK(c.time.max_steps == d.time.max_steps);
  CHECK(c.output.directory == d.output.directory);
  CHECK(c.output.profiles == d.output.profiles);
  CHECK(c.notices.empty());
}

TEST_CASE("config: output times past t_end are dropped with a notice", "[config]") {
  const Config c = load_config_string(with("[0.1, 0.2]", "[0.1, 0.5, 0.6, 0.9]"), {}, "case.yaml");
  CHECK(c.output.times == std::vector<double>{0.1, 0.5});  // t_end present: not duplicated
  REQUIRE(c.notices.size() == 1);
  CHECK(c.notices[0] == "case.yaml:17: output.times: dropped 2 output time(s) past time.t_end = 0.5: 0.6, 0.9");

  // Shortening t_end by an override drops times the same way.
  const Config s = load_config_string(base, {"time.t_end=0.15"}, "case.yaml");
  CHECK(s.output.times == std::vector<double>{0.1, 0.15});
  REQUIRE(s.notices.size() == 1);
  CHECK_THAT(s.notices[0], Contains("dropped 1 output time(s) past time.t_end = 0.15: 0.2"));
}

TEST_CASE("config: to_yaml round-trips through load_config_string", "[config]") {
  SECTION("defaults filled in") {
    const Config a = load_config_string(base, {}, "case.yaml");
    const std::string y = to_yaml(a);
    // Fully resolved: defaults appear in the text.
    CHECK_THAT(y, Contains("kernel: cubic_spline"));
    CHECK_THAT(y, Contains("table: ARKODE_DORMAND_PRINCE_7_4_5"));
    CHECK_THAT(y, Contains("body_force: [0, 0]"));
    CHECK_THAT(y, Contains("times: [0.1, 0.2, 0.5]"));
    const Config b = load_config_string(y, {}, "case.yaml");
    require_same(a, b);
    CHECK(to_yaml(b) == y);
  }
  SECTION("spacing, fixed dt, awkward numbers and directory") {
    const Config a = load_config_string(
        with("  particles_across: 20", "  spacing: 3.3333333333333335e-05",
             with("  t_end: 0.5", "  t_end: 0.30000000000000004\n  dt: 1e-7",
                  with("output:\n", "output:\n  directory: \"out dir/#1: \\\"x\\\"\"\n  profiles: false\n"))),
        {}, "case.yaml");
    REQUIRE(a.output.directory == "out dir/#1: \"x\"");
    REQUIRE(a.time.dt.has_value());
    const Config b = load_config_string(to_yaml(a), {}, "case.yaml");
    require_same(a, b);
    CHECK(b.discretization.spacing == 3.3333333333333335e-05);
    CHECK(b.time.t_end == 0.30000000000000004);
  }
  SECTION("control characters and line separators in the source and the directory") {
    // A newline, CR, tab, escape, NEL (U+0085) and LINE SEPARATOR (U+2028) in a path: the comment
    // naming the source stays one line, and the directory keeps every character.
    const std::string odd = "cfg\ndir\r\t\x1b\xc2\x85\xe2\x80\xa8x";
    const Config a = load_config_string(base, {"output.directory=\"nl\\nx\\u2028y\""}, odd + "/c.yaml");
    REQUIRE(a.output.directory == "nl\nx\xe2\x80\xa8y");
    const std::string y = to_yaml(a);
    CHECK_THAT(y, StartsWith("# Resolved sph-mol configuration (from cfg\\ndir\\r\\t\\x1b\\u0085\\u2028x/c.yaml); all defaults"));
    CHECK(y.find('\r') == std::string::npos);
    const Config b = load_config_string(y, {}, "config.yaml");
    require_same(a, b);
    CHECK(b.output.directory == a.output.directory);
    // The reloaded config names its own file, and writes back the same text but for that name.
    CHECK(to_yaml(b).substr(to_yaml(b).find('\n')) == y.substr(y.find('\n')));
  }
}

TEST_CASE("config: transport velocity and position noise of the shipped Taylor-Green file round-trip", "[config]") {
  const Config a = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/taylor_green.yaml");
  const auto& ta = a.discretization.transport_velocity;
  CHECK(ta.enabled);
  CHECK(ta.step_factor == 0.125);
  CHECK(ta.background_pressure == 0.0);  // rho0 c^2
  CHECK(ta.extra_stress);
  CHECK(a.discretization.position_noise == 0.01);
  const Config b = load_config_string(to_yaml(a), {}, "case.yaml");
  const auto& tb = b.discretization.transport_velocity;
  CHECK(tb.enabled == ta.enabled);
  CHECK(tb.step_factor == ta.step_factor);
  CHECK(tb.background_pressure == ta.background_pressure);
  CHECK(tb.extra_stress == ta.extra_stress);
  CHECK(b.discretization.position_noise == a.discretization.position_noise);
  // Switched off by an override: nothing of it is written back.
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/taylor_green.yaml",
                               {"discretization.transport_velocity.enabled=false"});
  CHECK_FALSE(c.discretization.transport_velocity.enabled);
  CHECK_THAT(to_yaml(c), !Contains("transport_velocity"));
}

TEST_CASE("config: time settings the integrator does not read get a notice", "[config]") {
  const auto notices_of = [](const std::vector<std::string>& sets) {
    std::string all;
    for (const auto& n : load_config_string(base, sets, "case.yaml").notices) all += n + "\n";
    return all;
  };
  // The leapfrogs read neither a table nor tolerances.
  const std::string lf = notices_of({"time.integrator=leapfrog", "time.table=ARKODE_HEUN_EULER_2_1_2", "time.rtol=1e-3", "time.atol=1e-9"});
  CHECK_THAT(lf, Contains("--set time.table=ARKODE_HEUN_EULER_2_1_2: time.table: has no effect: leapfrog takes no Butcher table"));
  CHECK_THAT(lf, Contains("time.rtol: has no effect: leapfrog takes fixed or CFL steps"));
  CHECK_THAT(lf, Contains("time.atol: has no effect"));
  // cvode_adams reads tolerances, no table.
  const std::string cv = notices_of({"time.integrator=cvode_adams", "time.table=ARKODE_HEUN_EULER_2_1_2", "time.rtol=1e-3"});
  CHECK_THAT(cv, Contains("time.table: has no effect"));
  CHECK_THAT(cv, !Contains("time.rtol"));
  // arkode_erk at a fixed step has no error control and no CFL bound.
  const std::string fixed = notices_of({"time.dt=1e-5", "time.rtol=1e-3", "time.cfl.acoustic=0.1"});
  CHECK_THAT(fixed, Contains("time.rtol: has no effect: arkode_erk with a fixed time.dt has no error control"));
  CHECK_THAT(fixed, Contains("time.cfl: has no effect: a fixed time.dt is not bounded by the CFL limits"));
  // Read: adaptive arkode_erk with everything; arkode_imex takes its tolerances at a fixed step too.
  CHECK(notices_of({"time.rtol=1e-3", "time.atol=1e-9", "time.table=ARKODE_HEUN_EULER_2_1_2", "time.cfl.acoustic=0.1"}).empty());
  CHECK(notices_of({"time.integrator=leapfrog", "time.cfl.acoustic=0.1"}).empty());
}

TEST_CASE("config: health.max_outflow_fraction without a face open to outflow gets a notice", "[config]") {
  const auto notices = [](const Config& c) {
    std::string all;
    for (const auto& n : c.notices) all += n + "\n";
    return all;
  };
  const std::string set = "health.max_outflow_fraction=0.2";
  CHECK_THAT(notices(load_config_string(base, {set}, "case.yaml")),
             Contains("--set health.max_outflow_fraction=0.2: health.max_outflow_fraction: has no effect: case 'couette' has no face "
                      "open to outflow"));
  const std::string dir = std::string(SPHMOL_SOURCE_DIR) + "/verification/";
  CHECK_THAT(notices(load_config(dir + "dam_break.yaml", {set})), !Contains("max_outflow_fraction"));
  CHECK_THAT(notices(load_config(dir + "hydrostatic.yaml", {set})), !Contains("max_outflow_fraction"));
  CHECK_THAT(notices(load_config(dir + "scene_tank.yaml", {set})), !Contains("max_outflow_fraction"));
  // The same scene with its top closed has no open face.
  CHECK_THAT(notices(load_config(dir + "scene_tank.yaml", {set, "scene.domain.open_faces=[]"})),
             Contains("health.max_outflow_fraction: has no effect: case 'scene' has no face open to outflow"));
}

TEST_CASE("config: discretization.wall_layers where no wall particles are made gets a notice", "[config]") {
  const auto notices = [](const Config& c) {
    std::string all;
    for (const auto& n : c.notices) all += n + "\n";
    return all;
  };
  const std::string dir = std::string(SPHMOL_SOURCE_DIR) + "/verification/";
  const std::string set = "discretization.wall_layers=2";
  CHECK_THAT(notices(load_config(dir + "taylor_green.yaml", {set})),
             Contains("discretization.wall_layers: has no effect: case 'taylor_green' makes no wall particles here (it has no walls)"));
  CHECK_THAT(notices(load_config(dir + "cavity.yaml", {set, "discretization.boundary=ghost", "discretization.wall_model=prescribed"})),
             Contains("discretization.wall_layers: has no effect: case 'cavity' makes no wall particles here (boundary 'ghost')"));
  // Read: wall particles, and the shock tube's end walls behind its ghost walls.
  CHECK_THAT(notices(load_config(dir + "cavity.yaml", {set})), !Contains("wall_layers"));
  CHECK_THAT(notices(load_config(dir + "shock_tube.yaml", {set})), !Contains("wall_layers"));
  CHECK_THAT(notices(load_config(dir + "scene_tank.yaml", {set})), !Contains("wall_layers"));
}

TEST_CASE("config: time.cfl.viscous where no viscous step limit applies gets a notice", "[config]") {
  const std::string dir = std::string(SPHMOL_SOURCE_DIR) + "/verification/";
  const std::string set = "time.cfl.viscous=0.1";
  // The implicit-viscosity integrators: the viscous limit drops out of their CFL step.
  for (const char* imex : {"time.integrator=leapfrog_imex", "time.integrator=arkode_imex"})
    CHECK(has_notice(load_config(dir + "couette.yaml", {set, imex}),
                     "time.cfl.viscous: has no effect: '" + std::string(imex).substr(16) +
                         "' treats the viscosity implicitly and no bulk_viscosity is set"));
  // An inviscid fluid.
  CHECK(has_notice(load_config(dir + "dam_break.yaml", {set}), "time.cfl.viscous: has no effect: the fluid is inviscid"));
  // Read: an explicit viscous run, a bulk viscosity with an implicit shear viscosity, the default value.
  CHECK_FALSE(has_notice(load_config(dir + "couette.yaml", {set, "time.integrator=leapfrog"}), "cfl.viscous"));
  CHECK_FALSE(has_notice(load_config(dir + "dam_break.yaml", {set, "discretization.bulk_viscosity=0.5"}), "cfl.viscous"));
  CHECK_FALSE(has_notice(load_config(dir + "couette.yaml", {"time.cfl.viscous=0.125", "time.integrator=leapfrog_imex"}), "cfl.viscous"));
  // At a fixed step the notice on time.cfl covers it.
  const Config fixed = load_config(dir + "couette.yaml", {set, "time.integrator=leapfrog", "time.dt=1e-5"});
  CHECK(has_notice(fixed, "time.cfl: has no effect"));
  CHECK_FALSE(has_notice(fixed, "cfl.viscous"));
}

TEST_CASE("config: combine_terms false where nothing combines gets a notice", "[config]") {
  const std::string dir = std::string(SPHMOL_SOURCE_DIR) + "/verification/";
  const std::string off = "discretization.combine_terms=false";
  CHECK(has_notice(load_config(dir + "couette.yaml", {off}), "discretization.combine_terms: has no effect: nothing to combine here"));
  CHECK(has_notice(load_config(dir + "shock_tube.yaml", {off}), "discretization.combine_terms: has no effect"));
  CHECK(has_notice(load_config(dir + "dam_break.yaml", {off, "discretization.artificial_viscosity.form=monaghan_1997",
                                                         "discretization.artificial_viscosity.eta=null"}),
                   "discretization.combine_terms: has no effect"));
  // The dam break's formulation combines: off is read (and measured against on).
  CHECK_FALSE(has_notice(load_config(dir + "dam_break.yaml", {off}), "combine_terms"));
  CHECK(load_config(dir + "dam_break.yaml").discretization.has_combinable_terms());
  CHECK_FALSE(load_config(dir + "dam_break.yaml", {"discretization.density_diffusion_form=hydrostatic_corrected"})
                  .discretization.has_combinable_terms());
}

TEST_CASE("config: the resolved config writes only the time settings the integrator reads", "[config]") {
  const Config lf = load_config_string(base, {"time.integrator=leapfrog", "time.dt=1e-5"});
  const std::string y = to_yaml(lf);
  CHECK_THAT(y, !Contains("rtol:"));
  CHECK_THAT(y, !Contains("table:"));
  CHECK_THAT(y, !Contains("cfl:"));
  // It loads back without notices.
  CHECK(load_config_string(y).notices.empty());
  const std::string erk = to_yaml(load_config_string(base));
  CHECK_THAT(erk, Contains("rtol:"));
  CHECK_THAT(erk, Contains("table:"));
  CHECK_THAT(erk, Contains("cfl:"));
}

TEST_CASE("config: tolerances and Krylov iterations are bounded where a run could not use them", "[config]") {
  CHECK_THAT(error_of(base, {"time.rtol=1e-300"}), Contains("time.rtol: 1e-300 is out of range (allowed: >= 1e-15"));
  // 2^32 + 1 would wrap to 1 in an int.
  const std::vector<std::string> imex{"time.integrator=leapfrog_imex", "time.krylov.max_iterations=4294967297"};
  CHECK_THAT(error_of(base, imex), Contains("time.krylov.max_iterations: 4294967297 is out of range (allowed: 1 to 1000)"));
  CHECK_THAT(error_of(base, {"time.integrator=arkode_imex", "time.krylov.solver=spgmr", "time.krylov.max_iterations=1000"}),
             Contains("(allowed: 1 to 200 with spgmr"));
  CHECK(load_config_string(base, {"time.integrator=leapfrog_imex", "time.krylov.max_iterations=1000"}).time.krylov.max_iterations == 1000);
}

TEST_CASE("config: output.every past t_end leaves t_end alone with a notice", "[config]") {
  // As output times past t_end are dropped: a file with `every` shortened by --set time.t_end loads.
  const Config c = load_config_string(base, {"output.times=[]", "output.every=0.2", "time.t_end=0.1"}, "case.yaml");
  CHECK(c.output.times == std::vector<double>{0.1});
  REQUIRE(c.notices.size() == 1);
  CHECK(c.notices[0] == "--set output.every=0.2: output.every: 0.2 s is past time.t_end = 0.1 s: the only output time is t_end");
}

TEST_CASE("config: parameters of the position correction auto did not choose get a notice", "[config]") {
  // They were dropped with nothing said but "auto: transport_velocity".
  const std::string tg = std::string(SPHMOL_SOURCE_DIR) + "/verification/taylor_green.yaml";
  const auto notices_of = [&](const std::vector<std::string>& sets) {
    std::string all;
    for (const auto& n : load_config(tg, sets).notices) all += n + "\n";
    return all;
  };
  CHECK_THAT(notices_of({}), !Contains("not used"));  // Re_h = 4: the transport velocity, with the file's parameters
  CHECK_THAT(notices_of({"discretization.particle_shifting={coefficient: 2}"}),
             Contains("discretization.particle_shifting.coefficient: not used: position_correction auto chose transport_velocity (Re_h"));
  CHECK_THAT(notices_of({"fluid.kinematic_viscosity=0.001"}),
             Contains("discretization.transport_velocity.step_factor: not used: position_correction auto chose particle_shifting (Re_h"));
  CHECK_THAT(notices_of({"discretization.position_correction=none"}),
             Contains("discretization.transport_velocity.step_factor: not used: position_correction none"));
}

TEST_CASE("config: wall_beta_max without Morris' wall model and vtk_walls without VTK get a notice", "[config]") {
  const auto notices_of = [](const std::vector<std::string>& sets) {
    std::string all;
    for (const auto& n : load_config_string(base, sets, "case.yaml").notices) all += n + "\n";
    return all;
  };
  CHECK_THAT(notices_of({"discretization.wall_model=prescribed", "discretization.wall_beta_max=2"}),
             Contains("discretization.wall_beta_max: has no effect: it caps the extrapolation of wall_model: morris (wall_model is 'prescribed')"));
  CHECK_THAT(notices_of({"discretization.wall_model=morris", "discretization.wall_beta_max=2"}), !Contains("wall_beta_max"));
  CHECK_THAT(notices_of({"output.vtk=false", "output.vtk_walls=false"}), Contains("output.vtk_walls: has no effect: output.vtk is false"));
  CHECK_THAT(notices_of({"output.vtk=true", "output.vtk_walls=false"}), !Contains("vtk_walls"));
  // The resolved config writes neither where it is not read, so it loads back without them.
  const Config c = load_config_string(base, {"discretization.wall_model=prescribed", "output.vtk=false"});
  CHECK_THAT(to_yaml(c), !Contains("wall_beta_max") && !Contains("vtk_walls"));
  CHECK(load_config_string(to_yaml(c)).notices.empty());
}
