// A run's output folder: one run at a time (lock), another run's results are not mixed with or
// silently overwritten (refused unless --overwrite, which deletes exactly that run's files), plots read
// only this run's files, and a restart continues in the folder its checkpoint lives in.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "run_helpers.hpp"
#include "support/process.hpp"

using namespace run_helpers;
using Catch::Matchers::Contains;

namespace {

const std::string kCouette = std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml";

// sph-mol with an argument vector; a short, small Couette run unless the arguments say otherwise.
test_support::ProcessResult couette_run(const fs::path& dir, std::vector<std::string> extra, const std::string& cwd = {}) {
  std::vector<std::string> args{"--config", kCouette, "-q", "--set", "discretization.particles_across=20",
                                "--set", "output.plots=false", "--set", "time.t_end=0.02"};
  args.insert(args.end(), extra.begin(), extra.end());
  return test_support::run_process(SPHMOL_BINARY, args, (dir / "stderr.txt").string(), cwd);
}

}  // namespace

TEST_CASE("output folder: a second run into a locked folder is refused", "[integration][output-folder]") {
  const fs::path dir = scratch("lock");
  const fs::path out = dir / "out";
  fs::create_directories(out);
  // Hold the lock as a running sph-mol would.
  const int fd = ::open((out / ".sph-mol.lock").c_str(), O_RDWR | O_CREAT, 0644);
  REQUIRE(fd >= 0);
  REQUIRE(::flock(fd, LOCK_EX | LOCK_NB) == 0);
  auto r = couette_run(dir, {"--output", out.string()});
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("another sph-mol run is writing there"));
  CHECK_FALSE(fs::exists(out / "summary.json"));
  ::close(fd);
  r = couette_run(dir, {"--output", out.string()});
  CHECK(r.code == 0);
  CHECK(fs::exists(out / "summary.json"));
}

TEST_CASE("output folder: another run's results are refused, --overwrite deletes exactly its files",
          "[integration][output-folder]") {
  const fs::path dir = scratch("reuse");
  const fs::path out = dir / "out";
  auto r = couette_run(dir, {"--output", out.string(), "--set", "output.times=[0.01]"});
  REQUIRE(r.code == 0);
  REQUIRE(fs::exists(out / "profile_t0.01.csv"));
  { std::ofstream(out / "notes.txt") << "mine"; }

  r = couette_run(dir, {"--output", out.string(), "--set", "output.times=[0.015]"});
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("holds the results of another run") && Contains("--overwrite"));
  CHECK(fs::exists(out / "profile_t0.01.csv"));  // untouched

  r = couette_run(dir, {"--output", out.string(), "--set", "output.times=[0.015]", "--overwrite"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_FALSE(fs::exists(out / "profile_t0.01.csv"));  // the first run's file is gone
  CHECK(fs::exists(out / "profile_t0.015.csv"));
  CHECK(fs::exists(out / "notes.txt"));                 // not a run's file: kept
  const auto s = json_file(out / "summary.json");
  const auto files = s["files"].get<std::vector<std::string>>();
  CHECK(std::find(files.begin(), files.end(), "profile_t0.01.csv") == files.end());
  CHECK(std::find(files.begin(), files.end(), "profile_t0.015.csv") != files.end());
  CHECK(std::find(files.begin(), files.end(), "summary.json") != files.end());
}

TEST_CASE("output folder: plots read only this run's files", "[integration][output-folder][plots]") {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    WARN("gnuplot not installed: skipped");
    return;
  }
  const fs::path dir = scratch("stale");
  const fs::path out = dir / "out";
  fs::create_directories(out);
  // A stale profile of some other run, without a summary (e.g. a run that was killed).
  { std::ofstream(out / "profile_t0.7.csv") << "y,u\n0,1\n"; }
  auto r = couette_run(dir, {"--output", out.string(), "--set", "output.plots=true"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const std::string script = slurp(out / "plot_profiles.gp");
  CHECK(script.find("profile_t0.02") != std::string::npos);
  CHECK(script.find("profile_t0.7") == std::string::npos);
}

TEST_CASE("output folder: the resolved config records the real folder, a restart continues there",
          "[integration][output-folder][restart]") {
  const fs::path dir = scratch("restart-home");
  const fs::path out = dir / "run";
  fs::create_directories(dir / "elsewhere");
  auto r = couette_run(dir, {"--output", out.string(), "--set", "output.checkpoint_every=0.01"});
  REQUIRE(r.code == 0);
  const std::string cfg = slurp(out / "config.yaml");
  CHECK_THAT(cfg, Contains("directory: \"" + fs::absolute(out).lexically_normal().string() + "\""));
  REQUIRE(fs::is_directory(out / "checkpoint-0.02"));

  // From another folder, without --output: the run continues in `out`, not in ./out/couette.
  r = test_support::run_process(SPHMOL_BINARY, {"--restart", (out / "checkpoint-0.02").string(), "-q", "--set", "time.t_end=0.03"},
                                (dir / "stderr.txt").string(), (dir / "elsewhere").string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(fs::is_empty(dir / "elsewhere"));
  const auto s = json_file(out / "summary.json");
  CHECK(s["t_end"] == 0.03);
  CHECK(s.contains("restarted_from"));
  const auto files = s["files"].get<std::vector<std::string>>();
  // The restarted run's list carries on the files written before the checkpoint.
  CHECK(std::find(files.begin(), files.end(), "profile_t0.02.csv") != files.end());
  CHECK(std::find(files.begin(), files.end(), "profile_t0.03.csv") != files.end());
  CHECK(std::find(files.begin(), files.end(), "checkpoint-0.02") != files.end());
  CHECK_THAT(r.err, !Contains("is not used"));

  // output.directory changed for the restart (--set here; an edited config.yaml alike): the run still
  // continues in `out`, and says that the other folder is not used instead of ignoring it silently.
  const fs::path other = dir / "other";
  r = test_support::run_process(SPHMOL_BINARY,
                                {"--restart", (out / "checkpoint-0.02").string(), "-q", "--set", "time.t_end=0.04",
                                 "--set", "output.directory=" + other.string()},
                                (dir / "stderr.txt").string(), (dir / "elsewhere").string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.err, Contains("output.directory " + other.string() + " is not used"));
  CHECK_THAT(r.err, Contains("--output " + other.string()));
  CHECK(!fs::exists(other));
  const auto s2 = json_file(out / "summary.json");
  CHECK(s2["t_end"] == 0.04);
  CHECK_THAT(s2["warnings"].dump(), Contains("is not used"));
}

TEST_CASE("output folder: a config.yaml inside the output folder is read before it is replaced",
          "[integration][output-folder]") {
  const fs::path dir = scratch("self-config");
  const fs::path out = dir / "out";
  auto r = couette_run(dir, {"--output", out.string()});
  REQUIRE(r.code == 0);
  const std::string resolved = slurp(out / "config.yaml");
  const double e1 = json_file(out / "summary.json")["final_errors"]["e_rms"].get<double>();
  // Rerun from the resolved config into its own folder.
  r = test_support::run_process(SPHMOL_BINARY, {"--config", (out / "config.yaml").string(), "-q", "--overwrite"},
                                (dir / "stderr.txt").string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  // The same settings (the first line names the file they came from).
  const auto body = [](const std::string& text) { return text.substr(text.find('\n')); };
  CHECK(body(slurp(out / "config.yaml")) == body(resolved));
  CHECK(json_file(out / "summary.json")["final_errors"]["e_rms"].get<double>() == e1);
}

TEST_CASE("output folder: a file size limit ends the run with a message and no truncated file",
          "[integration][output-folder]") {
  const fs::path dir = scratch("fsize");
  const fs::path out = dir / "out";
  // Made beforehand: a folder the run made and left holding only its lock file would be removed.
  fs::create_directories(out);
  // 4 KiB: the first profile (about 10 KiB) cannot be written.
  const auto r = test_support::run_process(
      SPHMOL_BINARY,
      {"--config", kCouette, "-q", "--set", "discretization.particles_across=20", "--set", "time.t_end=0.02",
       "--set", "output.plots=false", "--set", "output.checkpoint_every=0.005", "--output", out.string()},
      (dir / "stderr.txt").string(), {}, {}, 4096);
  INFO(r.err);
  CHECK(r.code == 1);  // not killed by SIGXFSZ (that would be 128 + 25)
  CHECK_THAT(r.err, Contains("file size limit"));
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    CHECK(name.find(".XXXXXX") == std::string::npos);
    // Only complete files: every regular file is below the limit, and no temporary (".name.abcdef") is left.
    if (e.is_regular_file() && name != ".sph-mol.lock") {
      CHECK(e.file_size() < 4096);
      CHECK(name.front() != '.');
    }
  }
}

TEST_CASE("output folder: a study into a folder in use is refused", "[integration][output-folder]") {
  const fs::path dir = scratch("study-lock");
  const fs::path out = dir / "out";
  fs::create_directories(out);
  const int fd = ::open((out / ".sph-mol.lock").c_str(), O_RDWR | O_CREAT, 0644);
  REQUIRE(fd >= 0);
  REQUIRE(::flock(fd, LOCK_EX | LOCK_NB) == 0);
  for (const std::string study : {"compare", "converge", "stability"}) {
    std::vector<std::string> args{study, "--config", kCouette, "--output", out.string(), "--set", "discretization.particles_across=20",
                                  "--set", "time.t_end=0.01"};
    if (study == "converge") args.insert(args.end(), {"--refine", "time", "--levels", "2"});
    if (study == "compare") args.insert(args.end(), {"--integrators", "leapfrog"});
    const auto r = test_support::run_process(SPHMOL_BINARY, args, (dir / "stderr.txt").string());
    INFO(study << ": " << r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("another sph-mol run is writing there"));
  }
  ::close(fd);
  CHECK(fs::is_empty(out) == false);  // only the lock file
  for (const auto& e : fs::directory_iterator(out)) CHECK(e.path().filename() == ".sph-mol.lock");
}
