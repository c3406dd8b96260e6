// The study subcommands end to end through the binary: files written, classes found.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace {
int run(const std::string& args, const std::string& log) {
  std::filesystem::create_directories("reports");
  const int rc = std::system((std::string(SPHMOL_BINARY) + " " + args + " >" + log + " 2>&1").c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}
nlohmann::json read_json(const std::string& path) {
  std::ifstream f(path);
  REQUIRE(f.good());
  return nlohmann::json::parse(f);
}
}  // namespace

TEST_CASE("sph-mol stability separates stable and blown-up runs on a coarse Poiseuille channel", "[integration][stability]") {
  // Leapfrog at 10 particles across: dt = 2e-3 s runs, 4e-3 s exceeds the viscous limit (measured).
  const std::string out = "reports/stability_poiseuille";
  REQUIRE(run("stability --config " SPHMOL_SOURCE_DIR "/verification/poiseuille.yaml --output " + out +
                  " --set discretization.particles_across=10 --set geometry.channel_length=1.0e-3 --set time.t_end=0.5"
                  " --set output.times=[0.5] --set time.integrator=leapfrog --set time.dt=2e-3"
                  " --sound-speed-factors 1 --step-factors 1,2",
              out + ".log") == 0);
  const auto j = read_json(out + "/stability.json");
  REQUIRE(j["runs"].size() == 2);
  CHECK(j["runs"][0]["class"] == "stable");
  CHECK(j["runs"][1]["class"] == "blown_up");
  CHECK(std::filesystem::exists(out + "/stability.csv"));
  CHECK(std::filesystem::exists(out + "/stability.png"));
}

TEST_CASE("sph-mol compare writes one row per integrator setting and names the fastest", "[integration][compare]") {
  const std::string out = "reports/compare_couette";
  REQUIRE(run("compare --config " SPHMOL_SOURCE_DIR "/verification/couette.yaml --output " + out +
                  " --integrators leapfrog_kdk,cvode_adams --set discretization.particles_across=20 --set time.t_end=0.01"
                  " --set output.times=[0.01]",
              out + ".log") == 0);
  const auto j = read_json(out + "/comparison.json");
  CHECK(j["runs"].size() == 4 + 5);  // 4 CFL factors, 5 tolerances
  for (const auto& r : j["runs"]) CHECK(r["status"] == "completed");
  CHECK_FALSE(j["fastest"][0]["fastest"].is_null());
  CHECK(std::filesystem::exists(out + "/comparison.csv"));
  CHECK(std::filesystem::exists(out + "/comparison.png"));
}
