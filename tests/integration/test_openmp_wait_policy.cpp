// The OpenMP wait policy sph-mol runs with (run/openmp_wait_policy.hpp): with more than one thread
// and no user choice, idle threads spin GOMP_SPINCOUNT = bounded_spin_count iterations (libgomp's
// default, 300,000, made two threads slower than one on a busy machine); a user's OMP_WAIT_POLICY
// or GOMP_SPINCOUNT is kept. libgomp prints the values it runs with when OMP_DISPLAY_ENV=verbose.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "sphmol/run/openmp_wait_policy.hpp"
#include "support/process.hpp"

namespace fs = std::filesystem;

namespace {

// The GOMP_SPINCOUNT values libgomp displayed, one per program start, in order.
std::vector<std::string> displayed_spin_counts(const std::string& err) {
  std::vector<std::string> out;
  const std::regex line(R"(GOMP_SPINCOUNT = '([0-9]+)')");
  for (auto it = std::sregex_iterator(err.begin(), err.end(), line); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1].str());
  return out;
}

}  // namespace

TEST_CASE("wait policy: the decision needs more than one thread and no user choice", "[openmp][integration]") {
  CHECK(sphmol::should_bound_openmp_spin(2, nullptr, nullptr));
  CHECK_FALSE(sphmol::should_bound_openmp_spin(1, nullptr, nullptr));
  CHECK_FALSE(sphmol::should_bound_openmp_spin(2, "passive", nullptr));
  CHECK_FALSE(sphmol::should_bound_openmp_spin(2, nullptr, "5000"));
  CHECK_FALSE(sphmol::should_bound_openmp_spin(2, nullptr, ""));
}

TEST_CASE("wait policy: two threads run with the bounded spin, a user's choice is kept", "[openmp][integration]") {
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) {
    WARN("OMP_WAIT_POLICY or GOMP_SPINCOUNT is set for the tests: the default cannot be observed");
    return;
  }
  const fs::path dir = fs::temp_directory_path() / ("sphmol-it-" + std::to_string(::getpid()) + "-wait-policy");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string err = (dir / "err").string();
  const std::vector<std::string> kernels = {"kernels", "--dimension", "1"};
  auto run = [&](const std::string& threads, std::vector<std::string> env) {
    std::vector<std::string> args = {"--threads", threads};
    args.insert(args.end(), kernels.begin(), kernels.end());
    env.emplace_back("OMP_DISPLAY_ENV=verbose");
    const auto r = test_support::run_process(SPHMOL_BINARY, args, err, {}, env);
    INFO(r.err);
    CHECK(r.code == 0);
    return displayed_spin_counts(r.err);
  };
  SECTION("two threads: executed once more, with the bounded spin") {
    const auto spins = run("2", {});
    REQUIRE(spins.size() == 2);  // the first start (libgomp's default), then the re-executed program
    CHECK(spins.back() == sphmol::bounded_spin_count);
  }
  SECTION("all cores (0) on a machine with several") {
    if (::sysconf(_SC_NPROCESSORS_ONLN) < 2) return;
    const auto spins = run("0", {});
    REQUIRE(spins.size() == 2);
    CHECK(spins.back() == sphmol::bounded_spin_count);
  }
  SECTION("one thread: libgomp's default, no second start") {
    const auto spins = run("1", {});
    REQUIRE(spins.size() == 1);
    CHECK(spins[0] != sphmol::bounded_spin_count);
  }
  SECTION("the user's GOMP_SPINCOUNT is kept") {
    const auto spins = run("2", {"GOMP_SPINCOUNT=1234"});
    REQUIRE(spins.size() == 1);
    CHECK(spins[0] == "1234");
  }
  SECTION("the user's OMP_WAIT_POLICY is kept") {
    const auto spins = run("2", {"OMP_WAIT_POLICY=passive"});
    REQUIRE(spins.size() == 1);
    CHECK(spins[0] == "0");  // passive: no spinning
  }
  fs::remove_all(dir);
}
