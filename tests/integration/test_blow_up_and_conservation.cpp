// Blow-up detection end to end (exit code 3, status and cause in summary.json, last good state),
// conservation diagnostics, and the new integrators on a short Couette run.
#include "sphmol/cases/channel/channel_settings.hpp"
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>
#include <nlohmann/json.hpp>

#include "sphmol/config/config.hpp"
#include "sphmol/run/run_case.hpp"
#include "support/process.hpp"

using namespace sphmol;

namespace {
const std::string couette = SPHMOL_SOURCE_DIR "/verification/couette.yaml";

std::string verification(const std::string& name) { return std::string(SPHMOL_SOURCE_DIR) + "/verification/" + name + ".yaml"; }

// Runs sph-mol with `args` (no shell) writing into a fresh `dir`; returns the exit code and stderr.
test_support::ProcessResult sph_mol(const std::string& dir, std::vector<std::string> args) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories("reports");
  args.insert(args.end(), {"--output", dir, "-q"});
  return test_support::run_process(SPHMOL_BINARY, args, dir + ".log");
}

nlohmann::json summary_of(const std::string& dir) {
  std::ifstream f(dir + "/summary.json");
  return f.good() ? nlohmann::json::parse(f) : nlohmann::json();
}
}  // namespace

TEST_CASE("physical health checks: unstable runs that completed with wrong answers end as blown_up", "[integration][blowup][health]") {
  // Each of these exited 0 with status "completed" before the physical checks (run/health_limits.hpp).
  SECTION("Taylor-Green with a fixed step 10x the acoustic CFL step gains kinetic energy with no input") {
    // Measured before: kinetic energy 0.25 J at t = 0 and 67 J at t = 0.25 s (L1 velocity error 12).
    const std::string dir = "reports/health_tg_dt";
    const auto r = sph_mol(dir, {"--config", verification("taylor_green"), "--set", "time.dt=0.01", "--set", "time.t_end=0.25",
                                 "--set", "output.times=[0.25]", "--set", "output.plots=false"});
    INFO(r.err);
    CHECK(r.code == 3);
    const auto s = summary_of(dir);
    REQUIRE(s.is_object());
    CHECK(s["status"] == "blown_up");
    const std::string cause = s["blow_up"]["cause"];
    CHECK((cause.find("kinetic energy") == 0 || cause.find("speed") == 0));
  }
  SECTION("Couette with a fixed leapfrog step past the viscous limit: speeds far above the plate speed") {
    // dt = 2.1e-4 s = 0.2 h^2/nu at 40 across; measured before: completed, e_rms 356 v0 at t = 0.1 s.
    const std::string dir = "reports/health_couette_dt";
    const auto r = sph_mol(dir, {"--config", couette, "--set", "time.integrator=leapfrog", "--set", "time.dt=2.1e-4", "--set",
                                 "time.t_end=0.1", "--set", "output.times=[0.1]", "--set", "output.plots=false"});
    INFO(r.err);
    CHECK(r.code == 3);
    const auto s = summary_of(dir);
    REQUIRE(s.is_object());
    CHECK(s["status"] == "blown_up");
    // The plate speed bounds the fluid's (maximum principle): the kinetic energy budget M v0^2 / 2
    // or the speed bound 10 v0, whichever is crossed first.
    const std::string cause = s["blow_up"]["cause"];
    INFO(cause);
    CHECK((cause.find("kinetic energy ") == 0 || cause.find("speed ") == 0));
    CHECK(s["blow_up"]["t"].get<double>() < 0.05);
  }
}

TEST_CASE("physical health checks: every shipped verification case completes at a CI resolution", "[integration][health]") {
  struct Run {
    const char* name;
    std::vector<std::string> set;
  };
  const std::vector<Run> runs = {
      {"couette", {"discretization.particles_across=20", "time.integrator=leapfrog", "time.t_end=0.3"}},
      {"poiseuille", {"discretization.particles_across=20", "time.integrator=leapfrog", "time.t_end=0.3"}},
      {"taylor_green", {"discretization.particles_across=20", "time.t_end=0.5"}},
      {"cavity", {"discretization.particles_across=12", "time.t_end=2"}},
      {"hydrostatic", {"discretization.particles_across=10", "time.t_end=2"}},
      {"dam_break", {"discretization.spacing=0.05", "time.t_end=0.5"}},
      // 4 rows across the tube: with 2 (spacing 0.0125) and h0 = 1.3 dx a particle leaves through a ghost wall at t = 0.16.
      {"shock_tube", {"discretization.spacing=0.00625"}},
      {"shock_tube_1d", {}},
      {"sod_1d", {}},
      {"sod", {"discretization.spacing=5e-3", "time.integrator=leapfrog"}},
      {"shock_tube_virtual", {"discretization.spacing=0.0125"}},
  };
  for (const auto& run : runs) {
    INFO(run.name);
    const std::string dir = std::string("reports/health_shipped_") + run.name;
    std::vector<std::string> args{"--config", verification(run.name), "--set", "output.plots=false", "--set", "output.times=[]"};
    for (const auto& s : run.set) args.insert(args.end(), {"--set", s});
    const auto r = sph_mol(dir, args);
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(summary_of(dir).value("status", "") == "completed");
  }
}

TEST_CASE("input errors found by the scene or the size estimate are exit 2 with the key, and write nothing", "[integration][health]") {
  struct Bad {
    std::string config;
    std::vector<std::string> set;
    std::string message;
  };
  const std::vector<Bad> bad = {
      {"dam_break", {"fluid.body_force=[0, 0]"}, "fluid.body_force: case 'dam_break' needs gravity"},
      {"dam_break", {"discretization.wall_pressure=rest", "discretization.boundary=ghost"}, "discretization.boundary: 'ghost' is not available for case 'dam_break': the tank is built from wall particles"},
      {"couette", {"discretization.particles_across=10"}, ": geometry.channel_length: the periodic length"},
      {"couette", {"fluid.kinematic_viscosity=0"}, "fluid.kinematic_viscosity: case 'couette' is driven by viscosity"},
      {"couette", {"discretization.particles_across=1000000000"}, "discretization.particles_across: the run needs about"},
      {"cavity", {"time.max_steps=1000"}, "time.dt: t_end / dt = 20 / 0.001 = 20000 steps, more than time.max_steps = 1000"},
  };
  for (const auto& b : bad) {
    INFO(b.message);
    const std::string dir = "reports/health_bad";
    std::vector<std::string> args{"--config", verification(b.config)};
    for (const auto& s : b.set) args.insert(args.end(), {"--set", s});
    const auto r = sph_mol(dir, args);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find("sph-mol: config error: ") == 0);
    CHECK(r.err.find(b.message) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir));
  }
}

TEST_CASE("threads: --threads above the core count warns in one line", "[integration][health]") {
  const std::string dir = "reports/health_threads";
  const std::string threads = std::to_string(std::thread::hardware_concurrency() + 1);
  const auto r = sph_mol(dir, {"--threads", threads, "--config", couette, "--set", "discretization.particles_across=20", "--set",
                               "time.t_end=0.001", "--set", "output.times=[]", "--set", "output.plots=false"});
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK(r.err.find("sph-mol: warning: --threads " + threads + " is more than the ") == 0);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

TEST_CASE("an unstable run ends cleanly as blown_up with exit code 3", "[integration][blowup]") {
  // Leapfrog with a fixed step 40x the viscous stability limit (0.125 h^2/nu ~ 5e-4 s at 20 across).
  // On 1 and 2 threads: the health check runs in parallel (run/health_check.hpp) and must name the
  // same particle and cause, and keep the same last good state.
  nlohmann::json first;
  for (const int threads : {1, 2}) {
    INFO("threads " << threads);
    const std::string out = "reports/blow_up_" + std::to_string(threads);
    std::filesystem::remove_all(out);
    std::filesystem::create_directories("reports");  // the stderr redirection below needs it
    const std::string cmd = std::string(SPHMOL_BINARY) + " --threads " + std::to_string(threads) + " --config " + couette +
                            " --output " + out +
                            " --set discretization.particles_across=20 --set time.integrator=leapfrog --set time.dt=2e-2"
                            " --set time.t_end=5 --set output.times=[5] 2>" + out + ".log";
    const int rc = std::system(cmd.c_str());
    REQUIRE(WIFEXITED(rc));
    CHECK(WEXITSTATUS(rc) == 3);
    std::ifstream f(out + "/summary.json");
    REQUIRE(f.good());
    const auto s = nlohmann::json::parse(f);
    CHECK(s["status"] == "blown_up");
    INFO(s["blow_up"].dump());
    CHECK(s["blow_up"]["t"].get<double>() < 5.0);
    CHECK_FALSE(s["blow_up"]["cause"].get<std::string>().empty());
    CHECK(std::filesystem::exists(out + "/last_good_state.csv"));
    std::ifstream g(out + "/last_good_state.csv");
    const std::string state((std::istreambuf_iterator<char>(g)), std::istreambuf_iterator<char>());
    CHECK(state.size() > 100);
    if (threads == 1) {
      first = s["blow_up"];
      first["state"] = state;
    } else {
      CHECK(s["blow_up"]["message"] == first["message"]);
      CHECK(s["blow_up"]["last_good_t"] == first["last_good_t"]);
      CHECK(state == first["state"].get<std::string>());
    }
  }
}

TEST_CASE("conservation: Couette y-momentum stays near 0 and a stable run reports status completed", "[integration][conservation]") {
  // x-momentum is not conserved (the moving plate drives the flow); y-momentum has no source on
  // average (the wall pressure forces on both sides balance), so its drift must stay tiny compared
  // with the x-momentum scale M v0.
  Config c = load_config(couette, {"discretization.particles_across=20", "time.t_end=0.1", "output.times=[0.05,0.1]"});
  RunOptions o;
  o.write_files = false;
  const auto s = run_case(c, o);
  CHECK(s["status"] == "completed");
  const auto& cons = s["conservation"];
  REQUIRE(cons["times"].size() == 3);
  const double M = cons["fluid_mass"].get<double>(), v0 = c.settings<ChannelSettings>().wall_velocity;
  const double px = cons["momentum"].back()[0].get<double>();
  const double py_drift = cons["momentum_drift"][1].get<double>();
  INFO("Px = " << px << ", Py drift = " << py_drift << ", M v0 = " << M * v0);
  CHECK(px > 0.01 * M * v0);  // the plate has set the fluid moving
  CHECK(std::abs(py_drift) < 1e-4 * M * v0);
  CHECK(cons["kinetic_energy"].back().get<double>() > 0.0);
}

TEST_CASE("leapfrog_kdk and cvode_adams agree with ARKODE on a short Couette run", "[integration][time]") {
  double e_ref = 0.0;
  for (const char* integ : {"arkode_erk", "leapfrog_kdk", "cvode_adams"}) {
    Config c = load_config(couette, {"discretization.particles_across=20", "time.t_end=0.05", "output.times=[0.05]",
                                     std::string("time.integrator=") + integ});
    RunOptions o;
    o.write_files = false;
    const auto s = run_case(c, o);
    const double e = s["final_errors"]["e_rms"].get<double>();
    INFO(integ << ": e_rms " << e);
    CHECK(s["status"] == "completed");
    CHECK(s["steps"].get<long>() > 0);
    CHECK(s["rhs_evals"].get<long>() >= s["steps"].get<long>());
    if (std::string(integ) == "arkode_erk") e_ref = e;
    else CHECK(std::abs(e - e_ref) < 0.05 * e_ref);
  }
}

TEST_CASE("a fixed time.dt beyond the widest stable CFL step at the start is warned about", "[integration][blowup][health]") {
  // hydrostatic_3d.yaml fixes dt = 0.15 h / c0 for its 8 particles across; refined to 64 across the
  // same dt is 1.2 h / c0, and the run blew up at t = 0.031 s with nothing saying why.
  SECTION("the hydrostatic tank refined eightfold with a fixed step: the summary and stderr say it") {
    // The tank as its file was before it took the CFL step: c0 = 29.7 m/s, dt = 0.15 h / c0 at 40 across.
    const std::string dir = "reports/dt_warning_refined";
    const auto r = sph_mol(dir, {"--config", verification("hydrostatic"), "--set", "discretization.particles_across=320", "--set",
                                 "fluid.eos.sound_speed=29.7", "--set", "time.dt=2.5e-4", "--set",
                                 "time.t_end=2.5e-4", "--set", "output.times=[2.5e-4]", "--set", "output.plots=false"});
    INFO(r.err);
    CHECK(r.code == 0);
    const auto s = summary_of(dir);
    REQUIRE(s.is_object());
    REQUIRE(s.contains("warnings"));
    const std::string w = s["warnings"][0];
    INFO(w);
    CHECK(w.find("time.dt = 0.00025 s is 1.1") == 0);  // 1.2 h / c0 against h / c at the compressed bottom
    CHECK(w.find("times the largest stable step at t = 0") != std::string::npos);
    CHECK(r.err.find("sph-mol: warning: time.dt") != std::string::npos);
  }
  SECTION("the shipped hydrostatic tank refined eightfold: its CFL step follows the spacing, no warning") {
    const std::string dir = "reports/dt_warning_refined_cfl";
    const auto r = sph_mol(dir, {"--config", verification("hydrostatic"), "--set", "discretization.particles_across=320", "--set",
                                 "time.t_end=2.5e-5", "--set", "output.times=[2.5e-5]", "--set", "output.plots=false"});
    INFO(r.err);
    CHECK(r.code == 0);
    const auto s = summary_of(dir);
    REQUIRE(s.is_object());
    CHECK(s["status"] == "completed");
    CHECK(s.value("warnings", nlohmann::json::array()).empty());
  }
  SECTION("Couette with a fixed leapfrog step past the viscous limit") {
    // dt = 2.1e-4 s = 0.2 h^2/nu at 40 across: 1.59 times the viscous limit 0.125 h^2/nu.
    const std::string dir = "reports/dt_warning_couette";
    const auto r = sph_mol(dir, {"--config", couette, "--set", "time.integrator=leapfrog", "--set", "time.dt=2.1e-4", "--set",
                                 "time.t_end=2.1e-3", "--set", "output.times=[2.1e-3]", "--set", "output.plots=false"});
    INFO(r.err);
    const auto s = summary_of(dir);
    REQUIRE(s.contains("warnings"));
    CHECK(s["warnings"][0].get<std::string>().find("time.dt = 0.00021 s is 1.59") == 0);
  }
  SECTION("shipped files whose fixed step is inside the stable ranges: no warning") {
    // scene_tank.yaml's step is 1.4 % above its own acoustic bound (coefficient 0.25), far inside 1.
    for (const char* file : {"hydrostatic_3d", "scene_tank", "cavity"}) {
      const std::string dir = std::string("reports/dt_warning_") + file;
      const auto r = sph_mol(dir, {"--config", verification(file), "--set", "time.t_end=1e-5", "--set", "output.times=[1e-5]",
                                   "--set", "output.plots=false"});
      INFO(file << ": " << r.err);
      CHECK(r.code == 0);
      CHECK(summary_of(dir).value("warnings", nlohmann::json::array()).empty());
    }
  }
}
