// Checkpoint/restart through the command line: a run stopped at t = 0.05 and continued with
// --restart to 0.1 ends in the same state as a run straight to 0.1 — bit for bit with both leapfrogs
// (their last RHS, the DKD XSPH correction and the cached CFL step are checkpointed), and within the integration
// tolerance with ARKODE (which restarts from (t, y) with the saved step as its first step).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "run_helpers.hpp"
#include "sphmol/io/double_codec.hpp"
#include "support/process.hpp"

using namespace run_helpers;

namespace {
nlohmann::json checkpoint_at(const fs::path& dir, const std::string& t) {
  return json_file(dir / ("checkpoint-" + t) / "checkpoint.json");
}
}  // namespace

TEST_CASE("restart: interrupted + restarted run = uninterrupted run", "[restart][integration]") {
  for (const std::string integrator : {"leapfrog", "leapfrog_kdk", "arkode_erk"}) {
    DYNAMIC_SECTION(integrator) {
      const fs::path dir = scratch("restart-" + integrator);
      const std::string common = couette("--set output.times=[0.05] --set output.checkpoint_every=0.025 --set time.integrator=" + integrator);
      REQUIRE(sph_mol(common + " --output '" + (dir / "whole").string() + "' --set time.t_end=0.1", dir / "e1").code == 0);
      REQUIRE(sph_mol(common + " --output '" + (dir / "first").string() + "' --set time.t_end=0.05", dir / "e2").code == 0);
      const auto r = sph_mol("-q --restart '" + (dir / "first" / "checkpoint-0.05").string() + "' --output '" +
                                 (dir / "second").string() + "' --set time.t_end=0.1",
                             dir / "e3");
      INFO(r.err);
      REQUIRE(r.code == 0);

      // Only the last two checkpoints the run wrote are kept.
      CHECK(fs::exists(dir / "whole" / "checkpoint-0.1"));
      CHECK(fs::exists(dir / "whole" / "checkpoint-0.075"));
      CHECK_FALSE(fs::exists(dir / "whole" / "checkpoint-0.05"));

      const auto a = checkpoint_at(dir / "whole", "0.1"), b = checkpoint_at(dir / "second", "0.1");
      const auto summary = json_file(dir / "second" / "summary.json");
      CHECK(summary["status"] == "completed");
      CHECK(summary["restarted_from"]["t"] == 0.05);
      // The measurements before the restart are carried over, and so is the split of the wall time.
      CHECK(summary["errors"].size() == 2);
      const auto first = checkpoint_at(dir / "first", "0.05");
      CHECK(first["rhs_seconds"].get<double>() > 0.0);
      CHECK(summary["wall_seconds_breakdown"]["rhs_without_search"].get<double>() + summary["wall_seconds_breakdown"]["neighbour_search"].get<double>() >
            first["rhs_seconds"].get<double>());
      if (integrator != "arkode_erk") {
        CHECK(a["state"] == b["state"]);
        CHECK(a["integrator_state"] == b["integrator_state"]);
        CHECK(summary["steps"] == json_file(dir / "whole" / "summary.json")["steps"]);
      } else {
        // Within the tolerance: |dy| <= 10 (rtol |y|max + atol) per block (positions, velocities).
        const auto ya = sphmol::decode_doubles(a["state"]), yb = sphmol::decode_doubles(b["state"]);
        REQUIRE(ya.size() == yb.size());
        const std::size_t half = ya.size() / 2;
        for (std::size_t begin : {std::size_t{0}, half}) {
          double dmax = 0.0, ymax = 0.0;
          for (std::size_t k = begin; k < begin + half; ++k) {
            dmax = std::max(dmax, std::abs(ya[k] - yb[k]));
            ymax = std::max(ymax, std::abs(ya[k]));
          }
          INFO("block " << begin << ": max |dy| = " << dmax << ", max |y| = " << ymax);
          CHECK(dmax <= 10.0 * (1e-6 * ymax + 1e-12));
        }
      }
    }
  }
}

TEST_CASE("restart: bad checkpoint paths are input errors (exit 2, nothing written)", "[restart][integration]") {
  const fs::path dir = scratch("restart-bad");
  auto r = sph_mol("--restart '" + (dir / "nope").string() + "' --output '" + (dir / "out").string() + "'", dir / "e");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains("config.yaml not found"));
  fs::create_directories(dir / "fake");
  std::ofstream(dir / "fake" / "config.yaml") << slurp(std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml");
  std::ofstream(dir / "fake" / "checkpoint.json") << "{\"format\": \"something else\"}";
  r = sph_mol("--restart '" + (dir / "fake").string() + "' --output '" + (dir / "out").string() + "'", dir / "e");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains("unknown format"));
  // A checkpoint of the previous format (without its config and list of written checkpoints) names both formats.
  std::ofstream(dir / "fake" / "checkpoint.json") << "{\"format\": \"sph-mol checkpoint 2\"}";
  r = sph_mol("--restart '" + (dir / "fake").string() + "' --output '" + (dir / "out").string() + "'", dir / "e");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains("'sph-mol checkpoint 2' (this build reads 'sph-mol checkpoint 3')"));
  CHECK_FALSE(fs::exists(dir / "out"));
}

namespace {
const std::string kCouette = std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml";

// sph-mol with an argument vector, killed after `seconds` (so a run that never ends fails the test).
test_support::ProcessResult run_bounded(const std::vector<std::string>& args, const fs::path& err, int seconds = 60) {
  std::vector<std::string> argv = {"-s", "KILL", std::to_string(seconds), SPHMOL_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  return test_support::run_process("/usr/bin/timeout", argv, err.string());
}

std::vector<std::string> couette_args(const fs::path& out, std::vector<std::string> extra) {
  std::vector<std::string> a = {"--config", kCouette, "--set", "discretization.particles_across=20", "--set",
                                "output.plots=false", "-q", "--output", out.string()};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}
}  // namespace

TEST_CASE("restart: a rerun keeps its own newest checkpoints beside later ones of an earlier run", "[restart][integration]") {
  const fs::path dir = scratch("restart-prune");
  const fs::path out = dir / "out";
  // First run to 0.1 leaves checkpoint-0.075 and checkpoint-0.1.
  REQUIRE(run_bounded(couette_args(out, {"--set", "time.t_end=0.1", "--set", "output.checkpoint_every=0.025"}), dir / "e1").code == 0);
  // As if that run had been killed before its summary (a finished run's folder is refused unless
  // --overwrite, which deletes its checkpoints: run/output_folder.hpp).
  fs::remove(out / "summary.json");
  // A rerun to 0.05 into the same directory: its checkpoints 0.025 and 0.05 stay, and so do the others.
  REQUIRE(run_bounded(couette_args(out, {"--set", "time.t_end=0.05", "--set", "output.checkpoint_every=0.025"}), dir / "e2").code == 0);
  CHECK(fs::exists(out / "checkpoint-0.025"));
  CHECK(fs::exists(out / "checkpoint-0.05"));
  CHECK(fs::exists(out / "checkpoint-0.075"));
  CHECK(fs::exists(out / "checkpoint-0.1"));
  // Restarted from 0.05 into the same directory to 0.1: the list continues (0.025 and 0.05 go when
  // 0.075 and 0.1 are written), and checkpoint-0.1 is now this run's.
  const auto r = run_bounded({"-q", "--restart", (out / "checkpoint-0.05").string(), "--output", out.string(), "--set",
                              "time.t_end=0.1"},
                             dir / "e3");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_FALSE(fs::exists(out / "checkpoint-0.025"));
  CHECK_FALSE(fs::exists(out / "checkpoint-0.05"));
  CHECK(fs::exists(out / "checkpoint-0.075"));
  const auto written = checkpoint_at(out, "0.1")["written"];
  REQUIRE(written.size() == 2);
  CHECK(fs::path(written[0].get<std::string>()).filename() == "checkpoint-0.075");
  CHECK(fs::path(written[1].get<std::string>()).filename() == "checkpoint-0.1");
}

TEST_CASE("restart: a checkpoint at t_end does the run's end again: summary and plots", "[restart][integration]") {
  // What a signal while gnuplot draws leaves (docs/output.md, "Plots"): the data files and a checkpoint
  // at t_end. It was refused ("nothing to continue"), so the run could not be finished but by hand.
  const fs::path dir = scratch("restart-at-end");
  const fs::path out = dir / "out";
  REQUIRE(run_bounded(couette_args(out, {"--set", "time.t_end=0.05", "--set", "output.checkpoint_every=0.05"}), dir / "e1").code == 0);
  const nlohmann::json first = json_file(out / "summary.json");
  fs::remove(out / "summary.json");
  const auto r = run_bounded({"--restart", (out / "checkpoint-0.05").string(), "--set", "output.plots=true"}, dir / "e2");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.err, Catch::Matchers::Contains("the checkpoint is at time.t_end = 0.05 s: nothing to integrate"));
  const nlohmann::json s = json_file(out / "summary.json");
  CHECK(s["status"] == "completed");
  CHECK(s["steps"] == first["steps"]);
  CHECK(s["final_errors"] == first["final_errors"]);
  CHECK(s["restarted_from"]["t"] == 0.05);
  CHECK(s["plots"] == nlohmann::json::array({"profiles.png"}));
  CHECK(fs::exists(out / "profiles.png"));
}

TEST_CASE("restart: a checkpoint with a NaN, negative or past-the-end time is refused (exit 2, file and field named)", "[restart][integration]") {
  const fs::path dir = scratch("restart-time");
  const fs::path out = dir / "out";
  REQUIRE(run_bounded(couette_args(out, {"--set", "time.t_end=0.05", "--set", "output.checkpoint_every=0.025"}), dir / "e1").code == 0);
  const fs::path cp = out / "checkpoint-0.05";
  const std::string file = (cp / "checkpoint.json").string();
  const nlohmann::json good = json_file(cp / "checkpoint.json");

  // After t_end: nothing to continue.
  auto r = run_bounded({"--restart", cp.string(), "--output", (dir / "r0").string(), "--set", "time.t_end=0.04"}, dir / "e");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains(file + ": t_bits: the checkpoint is at t = 0.050000 s, after time.t_end"));
  for (const auto& [bits, shown] : std::vector<std::pair<std::string, std::string>>{
           {sphmol::encode_doubles({std::nan("")}), "nan"}, {sphmol::encode_doubles({-0.01}), "-0.010000"}}) {
    auto j = good;
    j["t_bits"] = bits;
    std::ofstream(cp / "checkpoint.json") << j.dump();
    // Before this check a NaN time made the run loop spin forever, deaf to SIGTERM.
    r = run_bounded({"--restart", cp.string(), "--output", (dir / "r1").string(), "--set", "time.t_end=0.1"}, dir / "e", 30);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Matchers::Contains(file + ": t_bits: time " + shown + " is not a finite time >= 0"));
  }
  CHECK_FALSE(fs::exists(dir / "r0"));
  CHECK_FALSE(fs::exists(dir / "r1"));
}

TEST_CASE("restart: a change of the physics is refused with the key named, unless --force-physics-change", "[restart][integration]") {
  const fs::path dir = scratch("restart-physics");
  const fs::path out = dir / "out";
  REQUIRE(run_bounded(couette_args(out, {"--set", "time.t_end=0.05", "--set", "output.checkpoint_every=0.025"}), dir / "e1").code == 0);
  const fs::path cp = out / "checkpoint-0.05";
  const std::string file = (cp / "checkpoint.json").string();
  // --set of physics keys.
  for (const auto& [set, key] : std::vector<std::pair<std::string, std::string>>{
           {"fluid.kinematic_viscosity=2e-6", "fluid.kinematic_viscosity"},
           {"discretization.kernel=wendland_c2", "discretization.kernel"},
           {"discretization.smoothing_ratio=1.5", "discretization.smoothing_ratio"},
           {"fluid.eos.sound_speed=0.02", "fluid.eos.sound_speed"},
           {"discretization.momentum=symmetric_116", "discretization.momentum"}}) {
    const auto r = run_bounded({"--restart", cp.string(), "--output", (dir / "r").string(), "--set", "time.t_end=0.075",
                                "--set", set},
                               dir / "e");
    INFO(set << ": " << r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Matchers::Contains(file + ": config: the restart changes the physics"));
    CHECK_THAT(r.err, Catch::Matchers::Contains(key + " ("));
    CHECK_THAT(r.err, Catch::Matchers::Contains("--force-physics-change"));
  }
  CHECK_FALSE(fs::exists(dir / "r"));
  // An edited config.yaml in the checkpoint directory is compared too.
  const std::string yaml = slurp(cp / "config.yaml");
  std::string edited = yaml;
  const auto at = edited.find("kinematic_viscosity: ");
  REQUIRE(at != std::string::npos);
  edited = edited.substr(0, at + 21) + "3" + edited.substr(at + 21);  // 1e-06 -> 31e-06
  std::ofstream(cp / "config.yaml") << edited;
  auto r = run_bounded({"--restart", cp.string(), "--output", (dir / "r").string(), "--set", "time.t_end=0.075"}, dir / "e");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains("fluid.kinematic_viscosity ("));
  // Forced: it runs with the new viscosity.
  r = run_bounded({"--restart", cp.string(), "--output", (dir / "r").string(), "--set", "time.t_end=0.075", "--force-physics-change", "-q"},
                  dir / "e");
  INFO(r.err);
  CHECK(r.code == 0);
  std::ofstream(cp / "config.yaml") << yaml;
  // Keys that do not change the physics stay free: end time, outputs, tolerances.
  r = run_bounded({"--restart", cp.string(), "--output", (dir / "r2").string(), "--set", "time.t_end=0.075", "--set",
                   "time.rtol=1e-7", "--set", "output.profiles=false", "--set", "output.checkpoint_every=0.01", "-q"},
                  dir / "e");
  INFO(r.err);
  CHECK(r.code == 0);
  // --force-physics-change without --restart means nothing: refused.
  r = run_bounded({"--config", kCouette, "--force-physics-change", "--output", (dir / "r3").string()}, dir / "e");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains("--force-physics-change only applies to --restart"));
}

TEST_CASE("restart: a checkpoint interval that divides t_end writes a checkpoint at t_end", "[restart][integration]") {
  // 3 x 0.025 = 0.07500000000000001 > 0.075: before, the last checkpoint was never reached.
  const fs::path dir = scratch("restart-cp-end");
  const fs::path out = dir / "out";
  REQUIRE(run_bounded(couette_args(out, {"--set", "time.t_end=0.075", "--set", "output.checkpoint_every=0.025"}), dir / "e").code == 0);
  CHECK(fs::is_directory(out / "checkpoint-0.075"));
  CHECK(fs::is_directory(out / "checkpoint-0.05"));
}

TEST_CASE("restart: a malformed integrator state is bad input (exit 2)", "[restart][integration]") {
  const fs::path dir = scratch("restart-istate");
  const fs::path out = dir / "out";
  REQUIRE(run_bounded(couette_args(out, {"--set", "time.t_end=0.05", "--set", "output.checkpoint_every=0.025"}), dir / "e1").code == 0);
  const fs::path cp = out / "checkpoint-0.025";
  auto j = json_file(cp / "checkpoint.json");
  j["integrator_state"] = {{"garbage", true}};
  std::ofstream(cp / "checkpoint.json") << j.dump();
  const auto r = run_bounded({"--restart", cp.string(), "--output", (dir / "r").string()}, dir / "e");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains("integrator_state"));
  CHECK_FALSE(fs::exists(dir / "r"));
}
