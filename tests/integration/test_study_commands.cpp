// The study subcommands end to end through the binary: files written, classes found.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "sphmol/cases/case_module.hpp"
#include "support/process.hpp"

namespace {
// Runs sph-mol with `args` (an argument vector, no shell); stderr goes to `log`.
int run(const std::vector<std::string>& args, const std::string& log) {
  std::filesystem::create_directories("reports");
  return test_support::run_process(SPHMOL_BINARY, args, log).code;
}
// The same with a space-separated argument string (no argument here holds a space).
int run(const std::string& args, const std::string& log) {
  std::vector<std::string> v;
  std::istringstream in(args);
  for (std::string a; in >> a;) v.push_back(a);
  return run(v, log);
}
std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}
nlohmann::json read_json(const std::string& path) {
  std::ifstream f(path);
  REQUIRE(f.good());
  return nlohmann::json::parse(f);
}
bool finite_number(const nlohmann::json& v) { return v.is_number() && std::isfinite(v.get<double>()); }
// Runs `sph-mol compare` on the Couette case into `out` with the further arguments `args`, and reads
// the comparison it writes.
nlohmann::json compare_couette(const std::string& out, const std::string& args) {
  REQUIRE(run("compare --config " SPHMOL_SOURCE_DIR "/verification/couette.yaml --output " + out + " " + args,
              out + ".log") == 0);
  return read_json(out + "/comparison.json");
}
}  // namespace

TEST_CASE("sph-mol stability separates stable and blown-up runs on a coarse Poiseuille channel", "[integration][stability]") {
  // Leapfrog at 10 particles across: dt = 2e-3 s runs, 4e-3 s exceeds the viscous limit (measured).
  const std::string out = "reports/stability_poiseuille";
  REQUIRE(run("stability --config " SPHMOL_SOURCE_DIR "/verification/poiseuille.yaml --output " + out +
                                      " --set discretization.particles_across=10 --set geometry.channel_length=1.0e-3 --set time.t_end=0.5"
                                      " --set output.times=[0.5] --set time.integrator=leapfrog --set time.dt=2e-3"
                  " --sound-speed-factors 1 --step-factors 1,2",
              out + ".log") == 0);
  const auto j = read_json(out + "/stability.json");
  REQUIRE(j["runs"].size() == 2);
  CHECK(j["runs"][0]["class"] == "stable");
  CHECK(j["runs"][1]["class"] == "blown_up");
  CHECK(std::filesystem::exists(out + "/stability.csv"));
  CHECK(std::filesystem::exists(out + "/stability.png"));
}

TEST_CASE("sph-mol compare writes one row per integrator setting and names the fastest", "[integration][compare]") {
  const std::string out = "reports/compare_couette";
  const auto j = compare_couette(out, "--integrators leapfrog_kdk,cvode_adams --set discretization.particles_across=20"
                                      " --set time.t_end=0.01 --set output.times=[0.01]");
  CHECK(j["runs"].size() == 4 + 5);  // 4 CFL factors, 5 tolerances
  for (const auto& r : j["runs"]) CHECK(r["status"] == "completed");
  CHECK_FALSE(j["fastest"][0]["fastest"].is_null());
  CHECK(j["fastest"][0]["integrators"].size() == 2);
  CHECK(j["fastest"][0]["fastest"]["wall_seconds"].get<double>() > 0.0);
  CHECK(std::filesystem::exists(out + "/comparison.csv"));
  CHECK(std::filesystem::exists(out + "/comparison.png"));
  // Both charts are named in the JSON (the CPU-time one was not).
  if (!j["chart"].is_null()) {
    CHECK(j["cpu_chart"] == "comparison_cpu.png");
    CHECK(std::filesystem::exists(out + "/comparison_cpu.png"));
  }
}

TEST_CASE("sph-mol compare reports the implicit solves' Krylov iterations, 0 for the explicit runs", "[integration][compare]") {
  // Couette at 20 across to t = 0.02 s: leapfrog_imex solves the viscous kick once per step,
  // arkode_imex once per implicit stage; the explicit leapfrog and Dormand-Prince solve nothing.
  const std::string out = "reports/compare_couette_krylov";
  const auto j = compare_couette(out, "--integrators leapfrog,leapfrog_imex,arkode_imex,arkode_erk --step-factors 1"
                                      " --rtols 1e-5 --set discretization.particles_across=20"
                                      " --set time.t_end=0.02 --set output.times=[0.02]");
  REQUIRE(j["runs"].size() == 4);
  for (const auto& r : j["runs"]) {
    INFO(r.dump());
    const std::string name = r["integrator"].get<std::string>();
    const bool imex = name == "leapfrog_imex" || name == "arkode_imex";
    CHECK(r["status"] == "completed");
    if (imex) {
      CHECK(r["implicit_solves"].get<long>() > 0);
      CHECK(r["krylov_iterations"].get<long>() > 0);
      CHECK(r["krylov_iterations_per_step"].get<double>() > 0.0);
      CHECK(r["krylov_iterations_per_solve"].get<double>() > 0.0);
      CHECK(r["krylov_iterations_per_step"].get<double>() ==
            Approx(r["krylov_iterations"].get<double>() / r["steps"].get<double>()));
    } else {
      CHECK(r["implicit_solves"] == 0);
      CHECK(r["krylov_iterations"] == 0);
      CHECK(r["krylov_iterations_per_step"] == 0.0);
      CHECK(r["krylov_iterations_per_solve"].is_null());
    }
  }
  // leapfrog_imex: one solve per step; arkode_imex (ARK324L2SA): 3 implicit stages per attempted step.
  CHECK(j["runs"][1]["implicit_solves"] == j["runs"][1]["steps"]);
  CHECK(j["runs"][2]["implicit_solves"].get<long>() ==
        3 * (j["runs"][2]["steps"].get<long>() + j["runs"][2]["rejected_steps"].get<long>()));
  // The adaptive ARKODE runs count their CFL-limited steps; the leapfrogs leave it empty.
  CHECK(j["runs"][0]["stability_limited_steps"].is_null());
  CHECK(j["runs"][2]["stability_limited_steps"].is_number());
  CHECK(j["runs"][3]["stability_limited_steps"].is_number());

  // The CSV: one header row with units, the same columns in every row; the explicit runs' cells are
  // 0, their iterations per solve empty.
  std::ifstream f(out + "/comparison.csv");
  std::string line;
  REQUIRE(std::getline(f, line));
  const auto cells = [](const std::string& l) {
    std::vector<std::string> c;
    std::stringstream s(l);
    for (std::string x; std::getline(s, x, ',');) c.push_back(x);
    if (!l.empty() && l.back() == ',') c.emplace_back();
    return c;
  };
  const auto header = cells(line);
  std::map<std::string, std::size_t> col;
  for (std::size_t k = 0; k < header.size(); ++k) col[header[k]] = k;
  for (const char* name : {"rejected_steps [-]", "stability_limited_steps [-]", "implicit_solves [-]", "krylov_iterations [-]",
                           "krylov_iterations_per_step [-]", "krylov_iterations_per_solve [-]"})
    REQUIRE(col.count(name) == 1);
  std::map<std::string, std::vector<std::string>> rows;
  while (std::getline(f, line)) {
    const auto c = cells(line);
    REQUIRE(c.size() == header.size());
    rows[c[0]] = c;
  }
  REQUIRE(rows.size() == 4);
  for (const char* name : {"leapfrog_imex", "arkode_imex"}) {
    INFO(name);
    CHECK(std::stol(rows[name][col["krylov_iterations [-]"]]) > 0);
    CHECK(std::stod(rows[name][col["krylov_iterations_per_step [-]"]]) > 0.0);
    CHECK(std::stod(rows[name][col["krylov_iterations_per_solve [-]"]]) > 0.0);
  }
  for (const char* name : {"leapfrog", "arkode_erk"}) {
    INFO(name);
    CHECK(rows[name][col["implicit_solves [-]"]] == "0");
    CHECK(rows[name][col["krylov_iterations [-]"]] == "0");
    CHECK(rows[name][col["krylov_iterations_per_step [-]"]] == "0");
    CHECK(rows[name][col["krylov_iterations_per_solve [-]"]].empty());
  }
  // The printed table closes the log.
  CHECK_THAT(slurp(out + ".log"), Catch::Contains("its/step"));
}

TEST_CASE("sph-mol compare --reference-dt measures the time error: second order for the leapfrog", "[integration][compare]") {
  // Couette at 20 across to t = 0.01 s; CFL steps x 1, 1/2, 1/4; reference Verner 6 at dt = 1e-5.
  const std::string out = "reports/compare_couette_reference";
  const auto j = compare_couette(out, "--integrators leapfrog --reference-dt 1e-5 --step-factors 1,0.5,0.25 --targets 1e-4"
                                      " --set discretization.particles_across=20"
                                      " --set time.t_end=0.01 --set output.times=[0.01]");
  REQUIRE(j["runs"].size() == 3);
  std::vector<double> e;
  for (const auto& r : j["runs"]) e.push_back(r["error"].get<double>());
  INFO("time errors " << e[0] << " " << e[1] << " " << e[2]);
  CHECK(e[0] / e[1] > 3.0);  // ~4 for a second-order scheme
  CHECK(e[1] / e[2] > 3.0);
  CHECK(e[2] > 1e-12);
  CHECK(j["reference_run"]["dt"] == 1e-5);
  CHECK(j["fastest_exact_error"].size() == 1);  // the exact-error summary is kept alongside
  // 1e-4 lies between the first two runs: the cost is interpolated between them.
  const auto& f = j["fastest"][0]["fastest"];
  REQUIRE_FALSE(f.is_null());
  CHECK_FALSE(f["upper_bound"].get<bool>());
  CHECK(f["first_setting_at_target"] == "cfl_factor=0.5");
  const double rhs = f["rhs_evals"].get<double>();
  CHECK(rhs > j["runs"][0]["rhs_evals"].get<double>());
  CHECK(rhs < j["runs"][1]["rhs_evals"].get<double>());
}

TEST_CASE("sph-mol stability finds the slow symmetric oscillation of a long Poiseuille run", "[integration][stability]") {
  // 10 particles across, c = 2e-2 m/s (4 x the shipped c), dt = 2e-3 s, 60 s: the mean profile error
  // swings about its level by ~0.55 % of v0 instead of settling (Vukčević 2012, §9; README "Integrator
  // studies", measured 3 swings past 0.2 % after the start-up). Bounded: |e_signed| stays ~1 %.
  const std::string out = "reports/stability_poiseuille_oscillating";
  REQUIRE(run("stability --config " SPHMOL_SOURCE_DIR "/verification/poiseuille.yaml --output " + out +
                                      " --set discretization.particles_across=10 --set geometry.channel_length=1.0e-3 --set time.t_end=60"
                                      " --set output.plots=false --set time.integrator=leapfrog --set time.dt=2e-3"
                  " --sound-speed-factors 4 --step-factors 1 --samples 60",
              out + ".log") == 0);
  const auto j = read_json(out + "/stability.json");
  REQUIRE(j["runs"].size() == 1);
  const auto& r = j["runs"][0];
  INFO(r.dump());
  CHECK(r["class"] == "oscillating");
  CHECK(r["late_amplitude"].get<double>() > 0.002);
  CHECK(r["late_amplitude"].get<double>() < 0.02);
  CHECK(r["max_abs_e_signed"].get<double>() < 0.05);
}

namespace {
// A tiny run of each registered case (config file and --set overrides): a few hundred particles or
// fewer, one output time at t_end where the case measures its primary error.
struct TinyCase {
  std::string config;
  std::vector<std::string> sets;
};
const std::map<std::string, TinyCase>& tiny_cases() {
  static const std::map<std::string, TinyCase> cases = {
      {"couette", {"couette.yaml", {"discretization.particles_across=10", "geometry.channel_length=1.0e-3", "time.t_end=0.01", "output.times=[0.01]"}}},
      {"poiseuille", {"poiseuille.yaml", {"discretization.particles_across=10", "geometry.channel_length=1.0e-3", "time.t_end=0.01", "output.times=[0.01]"}}},
      {"taylor_green", {"taylor_green.yaml", {"discretization.particles_across=10", "time.t_end=0.05", "output.times=[0.05]"}}},
      {"hydrostatic",
       {"hydrostatic.yaml",
        {"discretization.particles_across=10", "fluid.body_force_ramp=0.05", "time.dt=5e-4", "time.t_end=0.15", "output.times=[0.15]"}}},
      {"cavity", {"cavity.yaml", {"discretization.particles_across=10", "time.t_end=0.05", "output.times=[0.05]"}}},
      {"dam_break", {"dam_break.yaml", {"discretization.spacing=0.1", "time.t_end=0.25", "output.times=[0.25]"}}},
      {"scene", {"scene_tank.yaml", {"discretization.spacing=0.02", "time.t_end=0.05", "output.times=[0.05]"}}},
      {"shock_tube", {"shock_tube_1d.yaml", {"discretization.spacing=0.02", "time.t_end=0.05", "output.times=[0.05]"}}},
      {"duct", {"duct_3d.yaml", {"discretization.particles_across=8", "geometry.length=1.0e-3", "time.t_end=0.01", "output.times=[0.01]"}}},
      {"beltrami", {"beltrami_3d.yaml", {"discretization.particles_across=8", "time.t_end=0.01", "output.times=[0.01]"}}},
  };
  return cases;
}
std::vector<std::string> study_args(const std::string& study, const std::string& name, const std::string& out,
                                    std::vector<std::string> extra) {
  const TinyCase& c = tiny_cases().at(name);
  std::vector<std::string> a = {study, "--config", std::string(SPHMOL_SOURCE_DIR) + "/verification/" + c.config, "--output", out};
  for (const auto& s : c.sets) {
    a.push_back("--set");
    a.push_back(s);
  }
  a.push_back("--set");
  a.push_back("output.plots=false");
  a.insert(a.end(), extra.begin(), extra.end());  // last: a --set here wins over the tiny sizes
  return a;
}
}  // namespace

TEST_CASE("every study runs on every registered case with finite errors", "[integration][studies][all_cases]") {
  for (const auto& name : sphmol::case_names()) {
    DYNAMIC_SECTION("case " << name) {
      REQUIRE(tiny_cases().count(name) == 1);  // a new case needs its tiny configuration here
      const std::string out = "reports/all_cases_" + name;
      {
        INFO("compare: " << slurp(out + "_compare.log"));
        REQUIRE(run(study_args("compare", name, out + "/compare", {"--integrators", "leapfrog", "--step-factors", "1,0.5"}),
                    out + "_compare.log") == 0);
        const auto j = read_json(out + "/compare/comparison.json");
        REQUIRE(j["runs"].size() == 2);
        for (const auto& r : j["runs"]) {
          CHECK(r["status"] == "completed");
          CHECK(finite_number(r["error"]));
        }
      }
      {
        // No --dt0: time.dt of the config, else the case's CFL step at t = 0.
        INFO("converge time: " << slurp(out + "_converge_time.log"));
        REQUIRE(run(study_args("converge", name, out + "/time", {"--refine", "time", "--levels", "2", "--integrators", "leapfrog"}),
                    out + "_converge_time.log") == 0);
        const auto j = read_json(out + "/time/convergence.json");
        REQUIRE(j["series"].size() == 1);
        for (const auto& e : j["series"][0]["errors"]) CHECK(finite_number(e));
        CHECK(finite_number(j["levels"][0]["dt"]));
      }
      {
        INFO("converge space: " << slurp(out + "_converge_space.log"));
        REQUIRE(run(study_args("converge", name, out + "/space", {"--refine", "space", "--levels", "2"}), out + "_converge_space.log") == 0);
        const auto j = read_json(out + "/space/convergence.json");
        REQUIRE(j["series"].size() == 1);
        for (const auto& e : j["series"][0]["errors"]) CHECK(finite_number(e));
        const auto& dx = j["series"][0]["spacings"];
        CHECK(dx[1].get<double>() == Approx(dx[0].get<double>() / 2));
      }
      {
        INFO("stability: " << slurp(out + "_stability.log"));
        REQUIRE(run(study_args("stability", name, out + "/stability",
                               {"--sound-speed-factors", "1", "--step-factors", "1", "--samples", "3"}),
                    out + "_stability.log") == 0);
        const auto j = read_json(out + "/stability/stability.json");
        REQUIRE(j["runs"].size() == 1);
        CHECK(j["runs"][0]["class"] != "blown_up");
        CHECK(finite_number(j["runs"][0]["error"]));
      }
    }
  }
}

TEST_CASE("studies of a user scene measure its quantity against a finer reference run", "[integration][studies][scene]") {
  const std::string out = "reports/scene_quantity";
  // compare: no --reference-dt, yet a reference run at a quarter of the CFL step measures every run.
  REQUIRE(run(study_args("compare", "scene", out + "/compare", {"--integrators", "leapfrog", "--step-factors", "1"}),
              out + "_compare.log") == 0);
  const auto c = read_json(out + "/compare/comparison.json");
  REQUIRE(c["reference_run"].is_object());
  CHECK(c["error"] == "relative velocity error vs reference run");
  CHECK_THAT(slurp(out + "_compare.log"), Catch::Contains("has no exact reference"));
  for (const auto& r : c["runs"]) CHECK(finite_number(r["exact_error"]));
  // converge in space: each level against one more level at half the finest spacing.
  REQUIRE(run(study_args("converge", "scene", out + "/space", {"--refine", "space", "--levels", "2"}), out + "_space.log") == 0);
  const auto s = read_json(out + "/space/convergence.json");
  CHECK_THAT(s["error_measure"].get<std::string>(), Catch::Contains("half the finest spacing"));
  REQUIRE(s["series"][0]["errors"].size() == 2);
  for (const auto& e : s["series"][0]["errors"]) CHECK(finite_number(e));
  CHECK_THAT(slurp(out + "_space.log"), Catch::Contains("reference level 2"));
}

TEST_CASE("compare names each case's own primary error and finds it finite", "[integration][compare]") {
  for (const auto& [name, key] : std::vector<std::pair<std::string, std::string>>{
           {"taylor_green", "L1_velocity"}, {"hydrostatic", "p_rms"}, {"cavity", "u_rms"}}) {
    DYNAMIC_SECTION(name) {
      const std::string out = "reports/compare_primary_" + name;
      REQUIRE(run(study_args("compare", name, out, {"--integrators", "leapfrog", "--step-factors", "1"}), out + ".log") == 0);
      const auto j = read_json(out + "/comparison.json");
      CHECK(j["error"] == key);
      REQUIRE(j["runs"].size() == 1);
      CHECK(finite_number(j["runs"][0]["error"]));
    }
  }
}

TEST_CASE("stability on the dam break: runs without a Martin-Moyce error are reported, not fatal", "[integration][stability]") {
  // t_end = 0.15 s is before the first Martin & Moyce point (T = 0.832, t = 0.188 s for a = 1 m): the
  // case leaves final_errors.front_rms_martin_moyce null, which the study used to read as a number.
  const std::string out = "reports/stability_dam_break";
  const auto args = study_args("stability", "dam_break", out, {"--sound-speed-factors", "0.5,1", "--step-factors", "1", "--samples", "3",
                                                               "--set", "time.t_end=0.15", "--set", "output.times=[0.15]"});
  const int code = run(args, out + ".log");
  INFO(slurp(out + ".log"));
  REQUIRE(code == 0);
  const auto j = read_json(out + "/stability.json");
  REQUIRE(j["runs"].size() == 2);
  for (const auto& r : j["runs"]) {
    CHECK(r["class"] == "not_blown_up");  // the dam break has no e_signed to test for oscillation
    CHECK(r["error"].is_null());
  }
  CHECK(slurp(out + ".log").find("front_rms_martin_moyce was not measured") != std::string::npos);
}

TEST_CASE("stability on a shock tube refuses sound speed factors whose waves reach the end walls before t_end",
          "[integration][stability][shock_tube]") {
  // The shipped 1D tube keeps its waves clear of the end walls until t = 0.2626 s, 1.31x its t_end. At
  // c x 2 they arrive at 0.1313 s, and the run ended "blown_up" with a gas particle pushed out of the
  // tube: the map called a step stable at c x 1 unstable at c x 2 for a reason that is not the step.
  const std::string v = std::string(SPHMOL_SOURCE_DIR) + "/verification/shock_tube_1d.yaml";
  const std::string out = "reports/stability_tube_walls";
  std::filesystem::remove_all(out);
  const int code = run({"stability", "--config", v, "--output", out, "--sound-speed-factors", "1,2", "--step-factors", "1",
                        "--samples", "3", "--set", "output.plots=false"},
                       out + ".log");
  const std::string log = slurp(out + ".log");
  INFO(log);
  CHECK(code == 2);
  CHECK(log.find("sound speed factor 2: ") != std::string::npos);
  CHECK(log.find("Give factors <= 1.313 for this t_end") != std::string::npos);
  CHECK(!std::filesystem::exists(out));  // refused before anything is written

  // Up to the limit the map runs, and the faster tube is not blown up.
  const int ok = run({"stability", "--config", v, "--output", out, "--sound-speed-factors", "1,1.3", "--step-factors", "1",
                      "--samples", "3", "--set", "output.plots=false"},
                     out + "_ok.log");
  INFO(slurp(out + "_ok.log"));
  REQUIRE(ok == 0);
  const auto j = read_json(out + "/stability.json");
  REQUIRE(j["runs"].size() == 2);
  for (const auto& r : j["runs"]) {
    CHECK(r["class"] == "not_blown_up");
    // The tube has no e_signed: nothing was measured for oscillation (these read 0 before).
    CHECK(r["sign_changes"].is_null());
    CHECK(r["late_amplitude"].is_null());
    CHECK(r["max_abs_e_signed"].is_null());
  }
}

TEST_CASE("converge --refine time without --dt0 starts from the case's CFL step", "[integration][converge]") {
  // Couette with CFL steps (no time.dt): dt0 is the leapfrog's stable step at t = 0.
  const std::string out = "reports/converge_cfl_dt0";
  INFO(slurp(out + ".log"));
  REQUIRE(run(study_args("converge", "couette", out, {"--refine", "time", "--levels", "3", "--integrators", "leapfrog"}), out + ".log") ==
          0);
  const auto j = read_json(out + "/convergence.json");
  const double dt0 = j["levels"][0]["dt"].get<double>();
  CHECK(dt0 > 0.0);
  CHECK(dt0 < 0.01);
  CHECK(j["levels"][2]["dt"].get<double>() == Approx(dt0 / 4));
  CHECK(j["series"][0]["observed_order"].get<double>() > 1.5);  // the leapfrog is second order
  CHECK(slurp(out + ".log").find("CFL step at t = 0") != std::string::npos);
}

TEST_CASE("converge --refine time says when dt0 does not divide t_end", "[integration][converge]") {
  // dt0 = 0.03 s and t_end = 0.05 s: every level ends with a shorter step, and nothing was said (the
  // observed orders scattered: Bogacki-Shampine 2.48).
  const std::string out = "reports/converge_uneven_dt0";
  std::filesystem::remove_all(out);
  REQUIRE(run({"converge", "--config", SPHMOL_SOURCE_DIR "/verification/shock_tube_1d.yaml", "--output", out, "--refine", "time", "--levels", "2",
               "--dt0", "0.03", "--integrators", "leapfrog", "--set", "discretization.spacing=0.02", "--set", "time.t_end=0.05", "--set",
               "output.times=[0.05]", "--set", "output.plots=false"},
              out + ".log") == 0);
  INFO(slurp(out + ".log"));
  CHECK(slurp(out + ".log").find("dt0 = 0.03 s does not divide t = 0.05 s") != std::string::npos);
  CHECK(read_json(out + "/convergence.json")["uniform_steps"] == false);
}

TEST_CASE("converge names levels whose error was not measured as such", "[integration][converge]") {
  // The dam break before the first Martin & Moyce point has no primary error: the log read "error inf"
  // while the CSV had an empty cell and the JSON null.
  const std::string out = "reports/converge_unmeasured";
  std::filesystem::remove_all(out);
  REQUIRE(run(study_args("converge", "dam_break", out, {"--refine", "space", "--levels", "2", "--set", "time.t_end=0.02", "--set", "output.times=[0.02]"}),
              out + ".log") == 0);
  const std::string log = slurp(out + ".log");
  INFO(log);
  CHECK(log.find("error not measured") != std::string::npos);
  CHECK(log.find("error inf") == std::string::npos);
  CHECK(log.find("observed order not measured") != std::string::npos);
}

TEST_CASE("studies draw no chart with output.plots false", "[integration][studies]") {
  // The charts were drawn whatever the config said.
  const std::string out = "reports/study_no_plots";
  std::filesystem::remove_all(out);
  REQUIRE(run(study_args("stability", "couette", out, {"--sound-speed-factors", "1", "--step-factors", "1", "--samples", "3"}),
              out + ".log") == 0);  // study_args gives output.plots=false
  CHECK_FALSE(std::filesystem::exists(out + "/stability.png"));
  CHECK_FALSE(std::filesystem::exists(out + "/stability.gp"));
  const auto j = read_json(out + "/stability.json");
  CHECK(j["chart"].is_null());
  CHECK(j["chart_problem"] == "output.plots is false");
}

TEST_CASE("converge --refine space keeps the configured integrator and refines a spacing", "[integration][converge]") {
  // The dam break gives discretization.spacing and uses the leapfrog.
  const std::string out = "reports/converge_space_spacing";
  INFO(slurp(out + ".log"));
  REQUIRE(run(study_args("converge", "dam_break", out, {"--refine", "space", "--levels", "2"}), out + ".log") == 0);
  const auto j = read_json(out + "/convergence.json");
  CHECK(j["series"][0]["integrator"] == "leapfrog");
  CHECK(j["levels"][1]["spacing"].get<double>() == Approx(0.05));
  CHECK(j["series"][0]["spacings"][0].get<double>() == Approx(0.1));
}

TEST_CASE("bad study command lines are exit 2 and name the option", "[integration][studies]") {
  const std::string cfg = std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml";
  for (const auto& [args, option] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"compare", "--config", cfg, "--integrators", "rk4"}, "--integrators"},
           {{"compare", "--config", cfg, "--integrators", ","}, "--integrators"},
           {{"compare", "--config", cfg, "--integrators", "leapfrog", "--rtols", "1e-3"}, "--rtols"},
           {{"compare", "--config", cfg, "--integrators", "cvode_adams", "--step-factors", "1"}, "--step-factors"},
           {{"compare", "--config", cfg, "--integrators", "leapfrog", "--output", ""}, "--output"},
           {{"converge", "--config", cfg, "--refine", "time", "--dt0", "-1"}, "--dt0"},
           {{"converge", "--config", cfg, "--refine", "space", "--dt0", "1e-3"}, "--dt0"},
           {{"converge", "--config", cfg, "--refine", "time", "--integrators", "cvode_adams"}, "--integrators"},
           {{"converge", "--config", cfg, "--refine", "time", "--integrators", "leapfrog:X"}, "--integrators"},
           {{"stability", "--config", cfg, "--sound-speed-factors", "0"}, "--sound-speed-factors"},
           {{"stability", "--config", cfg, "--step-factors", "1,-2"}, "--step-factors"},
           {{"stability", "--config", cfg, "--osc-threshold", "-1"}, "--osc-threshold"},
       }) {
    DYNAMIC_SECTION(args[0] << " " << option << " " << args.back()) {
      const std::string log = "reports/bad_study_option.log";
      CHECK(run(args, log) == 2);
      CHECK(slurp(log).find(option) != std::string::npos);
    }
  }
}

TEST_CASE("sph-mol compare leaves the error cells of a blown-up run empty, as the JSON has null", "[integration][compare]") {
  // leapfrog_kdk on Poiseuille 20 across at fixed steps 0.005 x (1, 1/2, 1/4, 1/8): the first three blow up.
  const std::string out = "reports/compare_blown_up";
  REQUIRE(run("--threads 1 compare --config " SPHMOL_SOURCE_DIR "/verification/poiseuille.yaml --output " + out +
                  " --integrators leapfrog_kdk --set discretization.particles_across=20 --set time.t_end=0.05"
                  " --set output.times=[0.05] --set time.dt=0.005",
              out + ".log") == 0);
  const auto j = read_json(out + "/comparison.json");
  std::ifstream f(out + "/comparison.csv");
  std::string line;
  std::getline(f, line);
  REQUIRE(j["runs"].size() == 4);
  int blown_up = 0;
  for (const auto& r : j["runs"]) {
    REQUIRE(std::getline(f, line));
    INFO(line);
    CHECK(line.find("inf") == std::string::npos);
    CHECK(line.find("nan") == std::string::npos);
    if (r["status"] == "blown_up") {
      ++blown_up;
      CHECK(r["error"].is_null());
      CHECK(line.size() > 11);
      CHECK(line.substr(line.size() - 11) == ",,,blown_up");  // error and exact_error empty
    } else {
      CHECK(finite_number(r["error"]));
    }
  }
  CHECK(blown_up >= 1);
}
