// The hydrostatic tank in 3D (verification/hydrostatic_3d.yaml) over 10 s of simulated time: the
// binary writes a 3D summary and the column holds p = rho0 g (H - z) without drifting.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/process.hpp"

namespace fs = std::filesystem;

TEST_CASE("hydrostatic 3D: the tank at rest over 10 s (10 x 10 x 10)", "[integration][hydrostatic]") {
  const fs::path dir = fs::temp_directory_path() / ("sphmol-it-" + std::to_string(::getpid()) + "-hydrostatic-3d");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path out = dir / "out";
  const auto r = test_support::run_process(
      SPHMOL_BINARY,
      {"--config", std::string(SPHMOL_SOURCE_DIR) + "/verification/hydrostatic_3d.yaml", "-q", "--set",
       "output.plots=false", "--output", out.string()},
      (dir / "stderr.txt").string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  std::ifstream in(out / "summary.json");
  REQUIRE(in);
  const auto s = nlohmann::json::parse(in);
  CHECK(s["dimension"] == 3);
  CHECK(s["t_end"].get<double>() >= 10.0);
  const auto& f = s["final_errors"];
  INFO(f.dump());
  CHECK(f["settled_outputs"].get<int>() == 6);  // t = 2, 3, 4, 5, 7.5, 10 (settled from 2 x ramp = 2 s)
  CHECK(f["p_rms"].get<double>() < P_RMS_BOUND);
  CHECK(f["p_max"].get<double>() < P_MAX_BOUND);
  CHECK(f["max_drift"].get<double>() < DRIFT_BOUND);
  fs::remove_all(dir);
}
