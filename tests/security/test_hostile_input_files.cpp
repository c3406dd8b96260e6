// Input files that would exhaust memory or never end: a config larger than the limit, /dev/zero, a
// FIFO, a directory. Each is refused before it is read, as bad input (exit 2) with the reason, and
// nothing is written.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/files.hpp"
#include "support/process.hpp"

namespace fs = std::filesystem;

namespace {

// Killed after 60 s: reading /dev/zero or a FIFO must not hang the test.
test_support::ProcessResult sph_mol(const std::vector<std::string>& args, const fs::path& err) {
  std::vector<std::string> argv = {"-s", "KILL", "60", SPHMOL_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  return test_support::run_process("/usr/bin/timeout", argv, err.string());
}
}  // namespace

TEST_CASE("config files that never end or are huge are refused before reading (exit 2)", "[security][input]") {
  const fs::path dir = test_support::fresh_dir("config-files");
  // 3 GiB, sparse (no disk used): larger than the 16 MiB limit.
  const fs::path huge = dir / "huge.yaml";
  std::ofstream(huge) << "case: couette\n";
  fs::resize_file(huge, std::uintmax_t{3} << 30);
  ::mkfifo((dir / "fifo.yaml").c_str(), 0644);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {huge.string(), "config file is larger than the limit of 16 MiB"},
      {"/dev/zero", "/dev/zero: not a regular file"},
      {(dir / "fifo.yaml").string(), "fifo.yaml: not a regular file"},
  };
  for (const auto& [path, message] : cases) {
    const auto r = sph_mol({"--config", path, "--output", (dir / "out").string()}, dir / "err");
    INFO(path << ": " << r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Matchers::Contains("sph-mol: config error: " + path + ": "));
    CHECK_THAT(r.err, Catch::Matchers::Contains(message));
  }
  // The study subcommands load configs through the same reader.
  const auto r = sph_mol({"converge", "--config", "/dev/zero", "--refine", "time", "--output", (dir / "out").string()}, dir / "err");
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains("not a regular file"));
  CHECK_FALSE(fs::exists(dir / "out"));
}

TEST_CASE("a checkpoint.json that is /dev/zero or deeply nested is refused (exit 2)", "[security][input]") {
  const fs::path dir = test_support::fresh_dir("checkpoint-files");
  const std::string couette = std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml";
  REQUIRE(sph_mol({"--config", couette, "--set", "discretization.particles_across=20", "--set", "output.plots=false", "-q",
                   "--set", "time.t_end=0.05", "--set", "output.checkpoint_every=0.05", "--output", (dir / "run").string()},
                  dir / "err")
              .code == 0);
  const fs::path cp = dir / "run" / "checkpoint-0.05";
  std::string text;
  {
    std::ifstream in(cp / "checkpoint.json");
    std::ostringstream s;
    s << in.rdbuf();
    text = s.str();
  }
  fs::remove(cp / "checkpoint.json");
  fs::create_symlink("/dev/zero", cp / "checkpoint.json");
  auto r = sph_mol({"--restart", cp.string(), "--output", (dir / "out").string(), "--set", "time.t_end=0.1"}, dir / "err");
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains("checkpoint.json: not a regular file"));
  fs::remove(cp / "checkpoint.json");
  // Nested without bound inside a field the reader copies (the recursive copy in the JSON library
  // overflowed the stack: SIGSEGV).
  const auto at = text.find("\"errors\":[");
  REQUIRE(at != std::string::npos);
  text.insert(at + 10, std::string(500'000, '[') + std::string(500'000, ']') + ",");
  std::ofstream(cp / "checkpoint.json") << text;
  r = sph_mol({"--restart", cp.string(), "--output", (dir / "out").string(), "--set", "time.t_end=0.1"}, dir / "err");
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains("nested deeper than 64 levels"));
  CHECK_FALSE(fs::exists(dir / "out"));
}

TEST_CASE("running out of memory is a message and exit 1, not an abort", "[security][input]") {
  // A config under the size limit whose parse needs more memory than the address-space limit allows
  // (a 15 MiB list: about a million YAML nodes).
  const fs::path dir = test_support::fresh_dir("out-of-memory");
  const fs::path cfg = dir / "big.yaml";
  {
    std::ofstream out(cfg);
    out << "case: couette\nextra: [1.5";
    for (int k = 0; k < 3'500'000; ++k) out << ",1.5";
    out << "]\n";
  }
  REQUIRE(fs::file_size(cfg) < (std::uintmax_t{16} << 20));
  const fs::path err = dir / "err";
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    const rlimit lim{400u << 20, 400u << 20};
    ::setrlimit(RLIMIT_AS, &lim);
    const int fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, STDERR_FILENO);
    ::execl(SPHMOL_BINARY, SPHMOL_BINARY, "--config", cfg.c_str(), "--output", (dir / "out").c_str(), nullptr);
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  std::ifstream in(err);
  std::ostringstream text;
  text << in.rdbuf();
  INFO(text.str());
  REQUIRE(WIFEXITED(status));  // before: std::terminate, SIGABRT
  CHECK(WEXITSTATUS(status) == 1);
  CHECK_THAT(text.str(), Catch::Matchers::Contains("sph-mol: out of memory"));
  CHECK_FALSE(fs::exists(dir / "out"));
}
