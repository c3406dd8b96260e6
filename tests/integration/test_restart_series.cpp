// A case's series through a checkpoint (Case::save_state): a run restarted from a checkpoint writes
// the same series CSV (front.csv, decay.csv: every output time, the ones before the checkpoint
// included) and the same summary errors and final errors as a run straight through, whether it
// restarts into its own folder or another one. Before, the rows before the checkpoint were lost from
// the CSV while the summary still counted them. A checkpoint without the case's state (an older
// sph-mol) still restarts, with a warning that names what is missing.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "run_helpers.hpp"

using namespace run_helpers;

namespace {

struct SeriesCase {
  std::string name, config, csv;
  std::string sets;  // a coarse, short run
};

const std::vector<SeriesCase>& series_cases() {
  static const std::vector<SeriesCase> list = {
      // dp = 0.04: 25 x 50 fluid particles, ~1 s per 0.1 s simulated.
      {"dam_break", "dam_break.yaml", "front.csv", "--set discretization.spacing=0.04"},
      // 20 x 20 particles.
      {"taylor_green", "taylor_green.yaml", "decay.csv", "--set discretization.particles_across=20"},
  };
  return list;
}

// Output times 0.02 ... 0.1: checkpoints at 0.04 and 0.06 fall on output times, so no run stops
// where the straight run does not.
const std::string kTimes = "--set 'output.times=[0.02, 0.04, 0.06, 0.08, 0.1]'";

std::string base(const SeriesCase& c) {
  return "-q --threads 1 --config '" + std::string(SPHMOL_SOURCE_DIR) + "/verification/" + c.config + "' " + c.sets +
         " --set output.plots=false " + kTimes;
}

// The summary's measurements: equal to the bit (JSON numbers of the same doubles).
void check_same_summary(const fs::path& a, const fs::path& b) {
  const auto sa = json_file(a / "summary.json"), sb = json_file(b / "summary.json");
  CHECK(sb["status"] == "completed");
  CHECK(sa["errors"].size() == 5);
  CHECK(sa["errors"] == sb["errors"]);
  CHECK(sa["final_errors"] == sb["final_errors"]);
}

}  // namespace

TEST_CASE("restart series: a restarted run's series CSV and summary equal a straight run's", "[restart][integration]") {
  for (const auto& c : series_cases()) {
    DYNAMIC_SECTION(c.name) {
      const fs::path dir = scratch("restart-series-" + c.name);
      const fs::path whole = dir / "whole", split = dir / "split", other = dir / "other";
      // Straight to 0.1, with checkpoints at 0.04 and 0.08.
      auto r = sph_mol(base(c) + " --set time.t_end=0.1 --set output.checkpoint_every=0.04 --output '" + whole.string() + "'", dir / "e1");
      INFO(r.err);
      REQUIRE(r.code == 0);
      // To 0.06 (checkpoint there), then on to 0.1 in the same folder.
      r = sph_mol(base(c) + " --set time.t_end=0.06 --set output.checkpoint_every=0.06 --output '" + split.string() + "'", dir / "e2");
      INFO(r.err);
      REQUIRE(r.code == 0);
      r = sph_mol("-q --threads 1 --restart '" + (split / "checkpoint-0.06").string() + "' --set time.t_end=0.1 " + kTimes, dir / "e3");
      INFO(r.err);
      REQUIRE(r.code == 0);
      // From the straight run's mid-run checkpoint at 0.04 into another folder.
      r = sph_mol("-q --threads 1 --restart '" + (whole / "checkpoint-0.04").string() + "' --output '" + other.string() + "'", dir / "e4");
      INFO(r.err);
      REQUIRE(r.code == 0);

      const std::string expected = slurp(whole / c.csv);
      CHECK(std::count(expected.begin(), expected.end(), '\n') == 6);  // the header and 5 output times
      CHECK(slurp(split / c.csv) == expected);
      CHECK(slurp(other / c.csv) == expected);
      check_same_summary(whole, split);
      check_same_summary(whole, other);
    }
  }
}

TEST_CASE("restart series: a checkpoint without the case's state restarts with a warning and a malformed one is refused",
          "[restart][integration]") {
  const SeriesCase& c = series_cases().front();  // the dam break
  const fs::path dir = scratch("restart-series-old");
  const fs::path cp = dir / "run" / "checkpoint-0.04";
  auto r = sph_mol(base(c) + " --set time.t_end=0.06 --set output.checkpoint_every=0.04 --output '" + (dir / "run").string() + "'", dir / "e1");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json good = json_file(cp / "checkpoint.json");
  REQUIRE(good.contains("case_state"));

  // As an earlier sph-mol wrote it: the run continues, says what is missing, and keeps the summary's errors.
  auto old = good;
  old.erase("case_state");
  std::ofstream(cp / "checkpoint.json") << old.dump();
  r = sph_mol("-q --restart '" + cp.string() + "' --output '" + (dir / "old").string() + "'", dir / "e2");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.err, Catch::Matchers::Contains("has no case_state"));
  CHECK_THAT(r.err, Catch::Matchers::Contains("miss the output times up to t = 0.04 s"));
  const auto s = json_file(dir / "old" / "summary.json");
  CHECK(s["errors"].size() == 3);
  REQUIRE(s.contains("warnings"));
  CHECK_THAT(s["warnings"].back().get<std::string>(), Catch::Matchers::Contains("has no case_state"));
  const std::string csv = slurp(dir / "old" / c.csv);
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 2);  // the header and 0.06

  // A malformed state is a bad checkpoint (exit 2), the field named, nothing written.
  for (const nlohmann::json& bad : {nlohmann::json{{"front_csv", 3}}, nlohmann::json::array(),
                                    nlohmann::json{{"front_csv", good["case_state"]["front_csv"]},
                                                   {"wall_crossed", nlohmann::json::array()},
                                                   {"min_wall_gap", "xyz"}}}) {
    auto j = good;
    j["case_state"] = bad;
    std::ofstream(cp / "checkpoint.json") << j.dump();
    r = sph_mol("-q --restart '" + cp.string() + "' --output '" + (dir / "bad").string() + "'", dir / "e3");
    INFO(bad.dump() << ": " << r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Matchers::Contains("case_state"));
    CHECK_FALSE(fs::exists(dir / "bad"));
  }
}

TEST_CASE("restart series: the dam break's front.csv and summary after SIGINT and --restart equal a straight run's",
          "[restart][signals][integration]") {
  const fs::path dir = scratch("restart-series-signal");
  const std::string cfg = std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml";
  // A leapfrog run stops between steps on the signal and restarts bit for bit (test_signals.cpp).
  const std::vector<std::string> common = {"-q", "--threads", "1", "--config", cfg, "--set", "discretization.spacing=0.04",
                                           "--set", "output.plots=false", "--set", "time.t_end=0.4", "--set",
                                           "output.times=[0.025, 0.05, 0.075, 0.1, 0.125, 0.15, 0.175, 0.2, 0.225, 0.25, 0.275, 0.3, 0.325, 0.35, 0.375, 0.4]", "--set", "output.checkpoint_every=0.05"};
  std::vector<std::string> args = common;
  args.insert(args.end(), {"--output", (dir / "run").string()});
  const pid_t pid = spawn(args, dir / "e1");
  REQUIRE(pid > 0);
  // Signal once the run is under way (first checkpoint written, an eighth of the run).
  const auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  bool ended = false;  // a run that failed to start is not waited for
  while (!fs::exists(dir / "run" / "checkpoint-0.05") && !(ended = ::waitpid(pid, &status, WNOHANG) == pid) &&
         std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (!ended) {
    ::kill(pid, SIGINT);
    ::waitpid(pid, &status, 0);
  }
  INFO(slurp(dir / "e1"));
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 128 + SIGINT);
  const double t = json_file(dir / "run" / "summary.json")["t_reached"].get<double>();
  REQUIRE(t < 0.4);
  char name[64];
  std::snprintf(name, sizeof name, "checkpoint-%.10g", t);
  // Into its own folder, as the tester did.
  auto r = sph_mol("-q --threads 1 --restart '" + (dir / "run" / name).string() + "'", dir / "e2");
  INFO(r.err);
  REQUIRE(r.code == 0);

  args = common;
  args.insert(args.end(), {"--output", (dir / "whole").string()});
  const pid_t straight = spawn(args, dir / "e3");
  REQUIRE(straight > 0);
  ::waitpid(straight, &status, 0);
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);

  const std::string expected = slurp(dir / "whole" / "front.csv");
  CHECK(std::count(expected.begin(), expected.end(), '\n') == 17);  // the header and 16 output times
  CHECK(slurp(dir / "run" / "front.csv") == expected);
  const auto sa = json_file(dir / "whole" / "summary.json"), sb = json_file(dir / "run" / "summary.json");
  CHECK(sb["status"] == "completed");
  CHECK(sa["errors"] == sb["errors"]);
  CHECK(sa["final_errors"] == sb["final_errors"]);
}
