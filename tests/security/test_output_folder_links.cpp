// The output folder and what --overwrite reads from it: a summary.json that is a FIFO, a device, a
// link or huge is refused before it is read (the folder lock is not held for ever); an output
// folder or a --restart checkpoint folder whose own name is a symbolic link is refused, naming the
// link and its target, for the run command, the studies and `kernels` alike (links higher up the
// path are layout and pass); an empty --output is refused; newlines in the config and output paths
// leave a config.yaml that a restart loads. The runs are tiny (Couette, 10 particles across).
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/files.hpp"
#include "support/process.hpp"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

const std::string kCouette = std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml";
const std::vector<std::string> kTiny = {"-q", "--set", "discretization.particles_across=10", "--set",
                                        "geometry.channel_length=1.0e-3", "--set", "time.t_end=0.002",
                                        "--set", "output.times=[0.002]", "--set", "output.plots=false"};

// Killed after 60 s: a FIFO read without care would hang the test.
test_support::ProcessResult sph_mol(std::vector<std::string> args, const fs::path& cwd) {
  std::vector<std::string> argv = {"-s", "KILL", "60", SPHMOL_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  return test_support::run_process("/usr/bin/timeout", argv, (cwd / "err.txt").string(), cwd.string());
}

std::vector<std::string> tiny_run(const std::vector<std::string>& extra) {
  std::vector<std::string> a = {"--config", kCouette};
  a.insert(a.end(), kTiny.begin(), kTiny.end());
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

}  // namespace

TEST_CASE("overwrite: a summary.json that is a FIFO or a device or a link or huge is refused (exit 2)", "[security][output]") {
  const fs::path dir = test_support::fresh_dir("overwrite-summary");
  std::ofstream(dir / "elsewhere.json") << R"({"files": ["keep.txt"]})";
  struct Planted {
    std::string name;
    std::string message;
  };
  const std::vector<Planted> cases = {{"fifo", "summary.json: not a regular file"},
                                      {"zero", "summary.json: a symbolic link"},
                                      {"link", "summary.json: a symbolic link"},
                                      {"huge", "run summary is larger than the limit of 64 MiB"}};
  for (const auto& c : cases) {
    DYNAMIC_SECTION(c.name) {
      const fs::path out = dir / c.name;
      fs::create_directories(out);
      std::ofstream(out / "keep.txt") << "not the run's";
      const fs::path summary = out / "summary.json";
      if (c.name == "fifo") ::mkfifo(summary.c_str(), 0644);
      if (c.name == "zero") fs::create_symlink("/dev/zero", summary);
      if (c.name == "link") fs::create_symlink(dir / "elsewhere.json", summary);
      if (c.name == "huge") {
        std::ofstream(summary) << "{}";
        fs::resize_file(summary, std::uintmax_t{1} << 30);  // sparse
      }
      const auto r = sph_mol(tiny_run({"--output", out.string(), "--overwrite"}), dir);
      INFO(r.err);
      CHECK(r.code == 2);
      CHECK_THAT(r.err, Contains("sph-mol: output directory " + out.string() + ": --overwrite reads"));
      CHECK_THAT(r.err, Contains(c.message));
      CHECK(fs::exists(out / "keep.txt"));
      CHECK_FALSE(fs::exists(out / "config.yaml"));
    }
  }
}

TEST_CASE("an output folder that is a symbolic link is refused and its target named (exit 2)", "[security][output]") {
  const fs::path dir = test_support::fresh_dir("output-link");
  fs::create_directories(dir / "victim");
  fs::create_symlink("victim", dir / "lnout");
  const std::string target = (dir / "victim").string();
  struct Command {
    std::string name;
    std::vector<std::string> args;
  };
  const std::vector<Command> commands = {
      {"run", tiny_run({})},
      {"compare", {"compare", "--config", kCouette, "--integrators", "leapfrog", "--step-factors", "1"}},
      {"converge", {"converge", "--config", kCouette, "--refine", "time", "--levels", "2", "--integrators", "leapfrog"}},
      {"stability", {"stability", "--config", kCouette, "--sound-speed-factors", "1", "--step-factors", "1"}}};
  for (const auto& cmd : commands)
    for (const std::string name : {"lnout", "lnout/", "lnout/."}) {
      DYNAMIC_SECTION(cmd.name << " --output " << name) {
        std::vector<std::string> args = cmd.args;
        args.insert(args.end(), {"--output", (dir / name).string()});
        const auto r = sph_mol(args, dir);
        INFO(r.err);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Contains("--output: " + (dir / name).string() + " is a symbolic link to " + target));
        CHECK_THAT(r.err, Contains("give " + target + " itself"));
        CHECK(fs::is_empty(dir / "victim"));
      }
    }
  SECTION("kernels --analysis hydrostatic --output") {
    const auto r = sph_mol({"kernels", "--analysis", "hydrostatic", "--kernel", "cubic_spline", "--output", (dir / "lnout").string()}, dir);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("sph-mol kernels: --output: " + (dir / "lnout").string() + " is a symbolic link to " + target));
    CHECK(fs::is_empty(dir / "victim"));
  }
  SECTION("output.directory of the config, claimed after the scene is built") {
    const auto r = sph_mol(tiny_run({"--set", "output.directory=\"" + (dir / "lnout").string() + "\""}), dir);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("sph-mol: output directory " + (dir / "lnout").string() + " is a symbolic link to " + target));
    CHECK(fs::is_empty(dir / "victim"));
  }
  SECTION("a link higher up the path is layout: the run writes below it") {
    const auto r = sph_mol(tiny_run({"--output", (dir / "lnout" / "run").string()}), dir);
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(fs::exists(dir / "victim" / "run" / "summary.json"));
  }
}

TEST_CASE("an empty --output is refused by the run command as by the studies (exit 2)", "[security][output]") {
  const fs::path dir = test_support::fresh_dir("output-empty");
  const auto r = sph_mol(tiny_run({"--output", ""}), dir);
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("sph-mol: --output: empty folder name"));
  CHECK_FALSE(fs::exists(dir / "out"));  // the config's output.directory (out/couette)
}

TEST_CASE("restart: a checkpoint folder or a run folder that is a symbolic link is refused (exit 2)", "[security][output]") {
  const fs::path dir = test_support::fresh_dir("restart-link");
  REQUIRE(sph_mol(tiny_run({"--set", "time.t_end=0.004", "--set", "output.times=[0.004]", "--set", "output.checkpoint_every=0.002",
                            "--output", (dir / "run").string()}),
                  dir)
              .code == 0);
  const fs::path cp = dir / "run" / "checkpoint-0.002";
  REQUIRE(fs::is_directory(cp));
  fs::create_symlink(cp, dir / "cplink");
  fs::create_symlink(dir / "run", dir / "runlink");
  SECTION("the checkpoint folder itself") {
    const auto r = sph_mol({"--restart", (dir / "cplink").string(), "-q", "--set", "time.t_end=0.006"}, dir);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("sph-mol: restart error: --restart " + (dir / "cplink").string() + " is a symbolic link to " +
                               cp.string()));
    CHECK_FALSE(fs::exists(dir / "summary.json"));  // the link's folder, where the run would have continued
  }
  SECTION("the run folder the restart continues in") {
    const auto r = sph_mol({"--restart", (dir / "runlink" / "checkpoint-0.002").string(), "-q", "--set", "time.t_end=0.006"}, dir);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains("output directory " + (dir / "runlink").string() + " is a symbolic link to " +
                               (dir / "run").string()));
  }
}

TEST_CASE("newlines in the config and output paths leave a config.yaml a restart loads", "[security][output]") {
  const fs::path dir = test_support::fresh_dir("newline-paths");
  const fs::path cfg_dir = dir / "cfg\ndir";
  fs::create_directories(cfg_dir);
  fs::copy_file(kCouette, cfg_dir / "c.yaml");
  const fs::path out = dir / "nl\nx";
  std::vector<std::string> args = {"--config", (cfg_dir / "c.yaml").string()};
  args.insert(args.end(), kTiny.begin(), kTiny.end());
  args.insert(args.end(), {"--set", "time.t_end=0.004", "--set", "output.times=[0.004]", "--set", "output.checkpoint_every=0.002",
                           "--output", out.string()});
  auto r = sph_mol(args, dir);
  INFO(r.err);
  REQUIRE(r.code == 0);
  const std::string yaml = test_support::slurp(out / "config.yaml");
  CHECK(yaml.substr(0, yaml.find('\n')).find("cfg\\ndir/c.yaml") != std::string::npos);
  // Restarted from the checkpoint (whose config.yaml names itself, in a folder with a newline), and
  // from the restarted run's checkpoint again.
  r = sph_mol({"--restart", (out / "checkpoint-0.002").string(), "-q", "--set", "time.t_end=0.006", "--set",
               "output.checkpoint_every=0.002", "--set", "output.times=[0.006]"},
              dir);
  INFO(r.err);
  CHECK(r.code == 0);
  r = sph_mol({"--restart", (out / "checkpoint-0.004").string(), "-q", "--set", "time.t_end=0.008", "--set",
               "output.times=[0.008]"},
              dir);
  INFO(r.err);
  CHECK(r.code == 0);
}

TEST_CASE("restart: a config.yaml with a YAML syntax error is a config error naming file and line (exit 2)", "[security][output]") {
  const fs::path dir = test_support::fresh_dir("restart-bad-yaml");
  REQUIRE(sph_mol(tiny_run({"--set", "time.t_end=0.004", "--set", "output.times=[0.004]", "--set", "output.checkpoint_every=0.002",
                            "--output", (dir / "run").string()}),
                  dir)
              .code == 0);
  const fs::path cp = dir / "run" / "checkpoint-0.002";
  std::ofstream(cp / "config.yaml") << "# comment\ncase: couette\nx\n)(: [\n";
  const auto r = sph_mol({"--restart", cp.string(), "-q", "--set", "time.t_end=0.006"}, dir);
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("sph-mol: config error: " + (cp / "config.yaml").string() + ":"));
  CHECK_THAT(r.err, Contains("YAML syntax error"));
}
