// summary.json names the program version and the git commit the binary was built from, so a
// result can be traced to its source: the commit of this checkout (git rev-parse HEAD, read here
// independently of the build), or "unknown" when the sources are not a git checkout.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <regex>
#include <sstream>

#include "run_helpers.hpp"
#include "sphmol/core/version.hpp"
#include "support/process.hpp"

using namespace run_helpers;

namespace {

// Standard output of `program args...` (argv, no shell), trailing newline removed; "" on failure.
std::string output_of(const std::string& program, const std::vector<std::string>& args) {
  int fd[2];
  if (::pipe(fd) != 0) return {};
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(fd[1], STDOUT_FILENO);
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, STDERR_FILENO);
    ::close(fd[0]);
    std::vector<char*> argv{const_cast<char*>(program.c_str())};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }
  ::close(fd[1]);
  std::string out;
  char buf[256];
  for (ssize_t n; (n = ::read(fd[0], buf, sizeof buf)) > 0;) out.append(buf, static_cast<std::size_t>(n));
  ::close(fd[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return {};
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

std::string git_program() {
  for (const char* p : {"/usr/bin/git", "/usr/local/bin/git", "/bin/git"})
    if (::access(p, X_OK) == 0) return p;
  return {};
}

}  // namespace

TEST_CASE("summary: program version and the git commit of the build", "[integration][summary]") {
  const fs::path dir = scratch("provenance");
  const auto r = test_support::run_process(
      SPHMOL_BINARY,
      {"--config", std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml", "-q", "--output", (dir / "o").string(),
       "--set", "discretization.particles_across=20", "--set", "time.t_end=0.01", "--set", "output.times=[0.01]", "--set",
       "output.plots=false"},
      (dir / "err").string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto s = json_file(dir / "o" / "summary.json");
  REQUIRE(s.contains("version"));
  REQUIRE(s.contains("git_commit"));
  CHECK(s["version"] == sphmol::version());
  const std::string commit = s["git_commit"].get<std::string>();
  CHECK(commit == sphmol::git_commit());

  const std::string git = git_program();
  std::string head, top;
  if (!git.empty()) {
    top = output_of(git, {"-C", SPHMOL_SOURCE_DIR, "rev-parse", "--show-toplevel"});
    head = output_of(git, {"-C", SPHMOL_SOURCE_DIR, "rev-parse", "HEAD"});
  }
  std::error_code ec;
  if (!head.empty() && fs::equivalent(top, SPHMOL_SOURCE_DIR, ec)) {
    // Built from this checkout: the build step records HEAD at every build, so the commit is HEAD, or
    // an ancestor of it when commits were made after the last build.
    REQUIRE(std::regex_match(commit, std::regex("[0-9a-f]{40}(-dirty)?")));
    const std::string built = commit.substr(0, 40);
    if (built != head) {
      WARN("the binary was built at " << built << ", HEAD is " << head << ": rebuild to record HEAD");
      CHECK(test_support::run_process(git, {"-C", SPHMOL_SOURCE_DIR, "merge-base", "--is-ancestor", built, "HEAD"},
                                      (dir / "git.err").string())
                .code == 0);
    }
  } else {
    CHECK(commit == "unknown");
  }
}
