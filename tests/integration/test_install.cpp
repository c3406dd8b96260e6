// cmake --install puts a working sph-mol in any prefix: the binary, the library, its headers and the
// Ghia tables, which the installed binary finds beside itself (not through the source tree).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <unistd.h>

#include "support/process.hpp"

namespace fs = std::filesystem;

TEST_CASE("install: cmake --install into a fresh prefix gives a runnable sph-mol with its data",
          "[integration][install]") {
  const fs::path root = fs::temp_directory_path() / ("sphmol-install-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  const fs::path prefix = root / "prefix with space";
  const std::string log = (root / "stderr.txt").string();

  const auto install = test_support::run_process(SPHMOL_CMAKE_COMMAND,
                                                 {"--install", SPHMOL_BUILD_DIR, "--prefix", prefix.string()}, log);
  INFO(install.err);
  REQUIRE(install.code == 0);
  const fs::path bin = prefix / "bin" / "sph-mol";
  CHECK(fs::is_regular_file(prefix / "lib" / "libsphmol.a"));
  CHECK(fs::is_regular_file(prefix / "include" / "sphmol" / "config" / "config.hpp"));
  CHECK(fs::is_regular_file(prefix / "include" / "sphmol" / "reference" / "data_directory.hpp"));
  CHECK(fs::is_regular_file(prefix / "share" / "sph-mol" / "ghia1982_u_vertical_centreline.csv"));
  CHECK(fs::is_regular_file(prefix / "share" / "sph-mol" / "ghia1982_v_horizontal_centreline.csv"));
  REQUIRE(fs::is_regular_file(bin));

  CHECK(test_support::run_process(bin.string(), {"--version"}, log).code == 0);

  // A tiny cavity (10 x 10, 20 steps): the reference is found and compared against.
  const fs::path out = root / "cavity";
  const auto run = test_support::run_process(
      bin.string(),
      {"--config", std::string(SPHMOL_SOURCE_DIR) + "/verification/cavity.yaml", "--output", out.string(), "--quiet",
       "--set", "discretization.particles_across=10", "--set", "time.dt=2e-3", "--set", "time.t_end=0.04",
       "--set", "output.times=[0.04]", "--set", "output.plots=false"},
      log, root.string());
  INFO(run.err);
  REQUIRE(run.code == 0);
  std::ifstream in(out / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  INFO(summary.dump(2));
  CHECK(summary.dump().find("Ghia") != std::string::npos);
  CHECK(summary.dump().find("no Ghia table") == std::string::npos);
  fs::remove_all(root);
}
