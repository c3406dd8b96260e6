// Output times do not change the solution: a fixed-step run that stops at ten output times ends in
// the same state, bit for bit, as one that stops only at its end (time/leapfrog_base.cpp steps on
// the grid k dt). Before, the time accumulated as t + dt drifted by round-off and the step shortened
// to land on each output time differed in its last bits between output lists; the cavity at Re 1000
// amplified that to different flows by t = 8 s.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/process.hpp"

namespace fs = std::filesystem;

namespace {

// The checkpoint the run wrote at its end (output.checkpoint_every = t_end).
nlohmann::json final_checkpoint(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_directory() && e.path().filename().string().rfind("checkpoint-", 0) == 0) {
      std::ifstream f(e.path() / "checkpoint.json");
      return nlohmann::json::parse(f);
    }
  return {};
}

nlohmann::json run(const fs::path& dir, const std::string& file, const std::vector<std::string>& sets) {
  fs::remove_all(dir);
  fs::create_directories(dir.parent_path());  // for the log beside the run's folder
  std::vector<std::string> args{"--config", std::string(SPHMOL_SOURCE_DIR) + "/verification/" + file, "--threads", "1",
                                "-q", "--output", dir.string(), "--set", "output.plots=false"};
  for (const auto& s : sets) args.insert(args.end(), {"--set", s});
  const auto r = test_support::run_process(SPHMOL_BINARY, args, dir.string() + ".log");
  INFO(r.err);
  REQUIRE(r.code == 0);
  return final_checkpoint(dir);
}

}  // namespace

TEST_CASE("output times do not change the solution (cavity, Re 1000, fixed step)", "[integration][output_times]") {
  const fs::path base = fs::temp_directory_path() / ("sphmol-output-times-" + std::to_string(::getpid()));
  const std::vector<std::string> common{"discretization.particles_across=16", "fluid.kinematic_viscosity=0.001",
                                        "time.dt=2.5e-3", "time.t_end=1.5", "output.checkpoint_every=1.5"};
  auto one = common, many = common;
  one.push_back("output.times=[1.5]");
  // Decimal times off the binary grid (0.1 = 40 dt is not 40 * 0.0025 in doubles) and one step apart.
  many.push_back("output.times=[0.1, 0.2, 0.3, 0.7, 0.7025, 0.9, 1.1, 1.3, 1.4975, 1.5]");
  const auto a = run(base / "one", "cavity.yaml", one), b = run(base / "many", "cavity.yaml", many);
  REQUIRE(a.contains("state"));
  REQUIRE(b.contains("state"));
  CHECK(a["t"] == b["t"]);
  CHECK(a["state"] == b["state"]);  // hex of the raw doubles: bit for bit
  CHECK(a["integrator_state"]["steps"] == b["integrator_state"]["steps"]);
  fs::remove_all(base);
}

TEST_CASE("the log names every output time as the files do", "[integration][output_times]") {
  // From the second line on the stream kept the wall time's precision of 2: t = 0.1125 read "0.11"
  // while the file was profile_t0.1125.csv.
  const fs::path dir = fs::temp_directory_path() / ("sphmol-it-" + std::to_string(::getpid()) + "-log-times");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto r = test_support::run_process(
      SPHMOL_BINARY,
      {"--config", std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml", "--threads", "1", "--output", (dir / "run").string(),
       "--set", "discretization.particles_across=20", "--set", "time.t_end=0.1125", "--set", "output.times=[0.0225, 0.045, 0.1125]",
       "--set", "output.plots=false"},
      (dir / "err").string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  for (const char* t : {"t =     0.0225 s", "t =      0.045 s", "t =     0.1125 s"}) CHECK(r.err.find(t) != std::string::npos);
  CHECK(fs::exists(dir / "run" / "profile_t0.1125.csv"));
  fs::remove_all(dir);
}
