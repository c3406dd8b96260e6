// The top-level command line: options of the run command given before a subcommand's name would be
// ignored by the subcommand, so they are refused (exit 2, the option named); --threads applies to all.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "run_helpers.hpp"
#include "support/process.hpp"

namespace fs = std::filesystem;

TEST_CASE("command line: run-command options before a subcommand are refused, naming the option", "[cli][integration]") {
  const fs::path dir = fs::temp_directory_path() / ("sphmol-it-" + std::to_string(::getpid()) + "-cli");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string cfg = std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml";
  const std::string err = (dir / "err").string();
  struct Case {
    std::vector<std::string> args;
    std::string option, sub;
  };
  const std::vector<Case> cases = {
      {{"--output", (dir / "x").string(), "compare", "--config", cfg, "--integrators", "leapfrog"}, "--output", "compare"},
      {{"--set", "time.t_end=0.01", "converge", "--config", cfg, "--refine", "time"}, "--set", "converge"},
      {{"--config", cfg, "stability", "--config", cfg}, "--config", "stability"},
      {{"-q", "kernels"}, "--quiet", "kernels"},
      {{"--restart", (dir / "cp").string(), "kernels"}, "--restart", "kernels"},
  };
  for (const auto& c : cases) {
    const auto r = test_support::run_process(SPHMOL_BINARY, c.args, err);
    INFO(c.option << " before " << c.sub << ": " << r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Matchers::Contains(c.option + " is an option of the run command, not of `" + c.sub + "`"));
  }
  CHECK_FALSE(fs::exists(dir / "x"));
  // --threads belongs to every command.
  const auto r = test_support::run_process(SPHMOL_BINARY, {"--threads", "1", "kernels", "--dimension", "1"}, err);
  INFO(r.err);
  CHECK(r.code == 0);
}

TEST_CASE("command line: a compare sweep not from coarse to fine is refused", "[cli][integration]") {
  // The fastest-at-error summary reads each integrator's runs coarse to fine: out of order it named a
  // fine run the fastest where a coarse one was cheaper, and a repeated value ran twice.
  const fs::path dir = fs::temp_directory_path() / ("sphmol-it-" + std::to_string(::getpid()) + "-sweep");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string cfg = std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml";
  const std::string err = (dir / "err").string();
  struct Case {
    std::vector<std::string> sweep;
    std::string option;
  };
  for (const Case& c : std::vector<Case>{{{"--integrators", "leapfrog", "--step-factors", "0.125,1"}, "--step-factors"},
                                         {{"--integrators", "leapfrog", "--step-factors", "1,1"}, "--step-factors"},
                                         {{"--integrators", "cvode_adams", "--rtols", "1e-6,1e-3"}, "--rtols"},
                                         {{"--integrators", "leapfrog,leapfrog"}, "--integrators"},
                                         {{"--integrators", "leapfrog,"}, "--integrators"}}) {
    std::vector<std::string> args{"compare", "--config", cfg, "--output", (dir / "x").string()};
    args.insert(args.end(), c.sweep.begin(), c.sweep.end());
    const auto r = test_support::run_process(SPHMOL_BINARY, args, err);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Matchers::StartsWith("sph-mol compare: " + c.option + ": "));
  }
  CHECK_FALSE(fs::exists(dir / "x"));
  fs::remove_all(dir);
}

namespace {

// sph-mol with `args` is refused as bad input: exit 2, `says` in its message, no folder `dir/x`.
void check_refused(const fs::path& dir, const std::vector<std::string>& args, const std::string& says) {
  const auto r = test_support::run_process(SPHMOL_BINARY, args, (dir / "err").string());
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains(says));
  CHECK(r.err.size() < 600);  // one message, not a number printed in 300 digits
  CHECK_FALSE(fs::exists(dir / "x"));
}

std::vector<std::string> with_sets(std::vector<std::string> args, const std::vector<std::string>& sets) {
  for (const auto& s : sets) args.insert(args.end(), {"--set", s});
  return args;
}

}  // namespace

TEST_CASE("command line: term combinations the assembly cannot build are config errors (exit 2), not failed runs", "[cli][integration]") {
  // They were thrown by the assembly as plain errors: exit 1, "run failed", which scripts count as a
  // numerical failure.
  const fs::path dir = run_helpers::scratch("combos");
  const std::string v = std::string(SPHMOL_SOURCE_DIR) + "/verification/";
  const auto run = [&](const std::string& config, const std::vector<std::string>& sets) {
    return with_sets({"--threads", "1", "-q", "--config", v + config, "--output", (dir / "x").string()}, sets);
  };
  check_refused(dir, run("couette.yaml", {"discretization.momentum=integral_approach"}),
                "sph-mol: config error: --set discretization.momentum=integral_approach: discretization.momentum: 'integral_approach' needs viscosity: none");
  check_refused(dir, run("dam_break.yaml", {"discretization.spacing=0.1", "discretization.momentum=integral_approach"}),
                "'integral_approach' is not available with density_diffusion");
  check_refused(dir, run("couette.yaml", {"discretization.wall_density_floor_width=0.01"}),
                "sph-mol: config error: discretization.wall_density_floor_width: is the floor of dynamic wall particles' density, and no wall is dynamic");
  fs::remove_all(dir);
}

TEST_CASE("command line: a number out of its range is named with its bound, not with the largest double", "[cli][integration]") {
  // CLI11's NonNegativeNumber and PositiveNumber printed "not in range 0.000000 to 1797693...", 300 digits.
  const fs::path dir = run_helpers::scratch("ranges");
  const std::string cfg = std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml";
  check_refused(dir, {"--threads", "-1", "--config", cfg}, "--threads: Value -1 is not a number >= 0");
  check_refused(dir, {"stability", "--config", cfg, "--sound-speed-factors", "1,-1"}, "--sound-speed-factors: Value -1 is not a number > 0");
  check_refused(dir, {"stability", "--config", cfg, "--osc-threshold", "x"}, "--osc-threshold: Value x is not a number >= 0");
  check_refused(dir, {"compare", "--config", cfg, "--step-factors", "0"}, "--step-factors: Value 0 is not a number > 0");
  check_refused(dir, {"converge", "--config", cfg, "--refine", "time", "--dt0", "-1e-3"}, "--dt0: Value -1e-3 is not a number > 0");
  fs::remove_all(dir);
}

TEST_CASE("command line: kernels refuses the options of the other mode", "[cli][integration]") {
  // --eps in the catalogue and --correction with the hydrostatic analysis were accepted and ignored.
  const fs::path dir = run_helpers::scratch("kernel-modes");
  check_refused(dir, {"kernels", "--eps", "0.02"}, "--eps is only used with --analysis hydrostatic");
  check_refused(dir, {"kernels", "--analysis", "hydrostatic", "--correction", "rkpm"}, "--correction is only used by the catalogue");
  fs::remove_all(dir);
}

TEST_CASE("command line: study lists without repeats and a reference step shorter than the run", "[cli][integration]") {
  // stability ran a repeated factor twice (duplicate rows), compare reported a repeated target twice,
  // and compare --reference-dt longer than t_end blew its reference run up and exited 1.
  const fs::path dir = run_helpers::scratch("study-lists");
  const std::string tube = std::string(SPHMOL_SOURCE_DIR) + "/verification/shock_tube_1d.yaml";
  const auto study = [&](std::vector<std::string> args) {
    args.insert(args.end(), {"--config", tube, "--output", (dir / "x").string()});
    return with_sets(args, {"discretization.spacing=0.02", "time.t_end=0.05", "output.times=[0.05]"});
  };
  check_refused(dir, study({"stability", "--sound-speed-factors", "0.5,1", "--step-factors", "1,4,1"}), "--step-factors: gives 1 twice");
  check_refused(dir, study({"stability", "--sound-speed-factors", "1,1"}), "--sound-speed-factors: gives 1 twice");
  check_refused(dir, study({"compare", "--integrators", "leapfrog", "--targets", "0.02,0.02"}), "--targets: gives 0.02 twice");
  check_refused(dir, study({"compare", "--integrators", "leapfrog", "--step-factors", "1", "--reference-dt", "0.1"}),
                "--reference-dt 0.1 s is not shorter than time.t_end = 0.05 s");
  fs::remove_all(dir);
}

TEST_CASE("command line: --rebalance-threshold outside mpirun says it has no effect", "[cli][integration]") {
  const fs::path dir = run_helpers::scratch("rebalance");
  const auto r = test_support::run_process(
      SPHMOL_BINARY,
      with_sets({"--threads", "1", "-q", "--config", std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml", "--output",
                 (dir / "x").string(), "--rebalance-threshold", "2"},
                {"discretization.particles_across=20", "time.t_end=0.01", "output.times=[0.01]"}),
      (dir / "err").string());
  INFO(r.err);
  if (r.code == 2) {  // a build without MPI has no such option
    WARN("no --rebalance-threshold in this build: " << r.err);
    return;
  }
  CHECK(r.code == 0);
  CHECK_THAT(r.err, Catch::Matchers::Contains("--rebalance-threshold has no effect: the run is not split over MPI ranks"));
  fs::remove_all(dir);
}
