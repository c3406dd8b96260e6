// Files the program creates never follow a link planted in the output folder, and a failed write
// (full disk, ulimit -f) leaves neither a truncated file under the final name nor a temporary.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "sphmol/io/atomic_file.hpp"

#include "support/files.hpp"

namespace fs = std::filesystem;

namespace {

std::size_t entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST_CASE("atomic write: a link planted at the old predictable temporary name is not followed", "[security][io]") {
  const fs::path dir = test_support::fresh_dir("tmp-link");
  const fs::path victim = dir / "victim.txt";
  { std::ofstream(victim) << "precious"; }
  fs::create_symlink(victim, dir / "summary.json.tmp");
  sphmol::write_file_atomically((dir / "summary.json").string(), "{}\n");
  CHECK(test_support::slurp(victim) == "precious");
  CHECK(test_support::slurp(dir / "summary.json") == "{}\n");
  CHECK(fs::is_symlink(dir / "summary.json.tmp"));  // left as it was: not ours
  fs::remove_all(dir);
}

TEST_CASE("atomic write: a link at the final name is replaced, its target untouched", "[security][io]") {
  const fs::path dir = test_support::fresh_dir("final-link");
  const fs::path victim = dir / "victim.txt";
  { std::ofstream(victim) << "precious"; }
  fs::create_symlink(victim, dir / "summary.json");
  sphmol::write_file_atomically((dir / "summary.json").string(), "new");
  CHECK(test_support::slurp(victim) == "precious");
  CHECK(!fs::is_symlink(dir / "summary.json"));
  CHECK(test_support::slurp(dir / "summary.json") == "new");
  fs::remove_all(dir);
}

TEST_CASE("atomic write: a file size limit leaves the old file and no temporary", "[security][io]") {
  const fs::path dir = test_support::fresh_dir("fsize");
  const fs::path target = dir / "big.csv";
  { std::ofstream(target) << "old"; }
  // In a child, so the limit and the ignored signal do not reach the test process.
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit lim{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &lim);
    try {
      sphmol::write_file_atomically(target.string(), std::string(1 << 16, 'x'));
    } catch (const std::exception& e) {
      ::_exit(std::string(e.what()).find("file size limit") != std::string::npos ? 0 : 2);
    }
    ::_exit(1);  // no error: the limit was not noticed
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(test_support::slurp(target) == "old");
  CHECK(entries(dir) == 1);  // no temporary left behind
  fs::remove_all(dir);
}

TEST_CASE("atomic write: a missing directory is an error naming the file", "[security][io]") {
  const fs::path dir = test_support::fresh_dir("missing");
  try {
    sphmol::write_file_atomically((dir / "no" / "such" / "file.txt").string(), "x");
    FAIL("no error");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("file.txt") != std::string::npos);
  }
  fs::remove_all(dir);
}
