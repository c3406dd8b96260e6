// Sod's shock tube in 1D and 2D (verification/sod_1d.yaml, sod.yaml) and the 2D against the 1D
// Hernquist-Katz tube (shock_tube.yaml, shock_tube_1d.yaml), each at its shipped resolution with the
// leapfrog (one RHS evaluation per step; the errors are spatial, docs/verification.md).
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/process.hpp"

namespace {

const std::string source_dir = SPHMOL_SOURCE_DIR;

// Runs the binary on a shipped config with `sets` (each a --set value); the summary, or null.
nlohmann::json run(const std::string& config, const std::string& tag, const std::vector<std::string>& sets) {
  const auto out = std::filesystem::temp_directory_path() / ("sphmol-it-sod-" + tag);
  std::filesystem::remove_all(out);
  std::vector<std::string> args = {"--threads", "1", "--config", source_dir + "/verification/" + config, "--output",
                                   out.string(), "--set", "time.integrator=leapfrog", "--set", "output.plots=false"};
  for (const auto& s : sets) {
    args.push_back("--set");
    args.push_back(s);
  }
  const auto r = test_support::run_process(SPHMOL_BINARY, args, out.string() + ".err");
  INFO(r.err);
  if (r.code != 0) return nullptr;
  std::ifstream in(out / "summary.json");
  return nlohmann::json::parse(in);
}

double l1(const nlohmann::json& s, const char* key) { return s["final_errors"][key].get<double>(); }

}  // namespace

// Measured (leapfrog, 450 particles): L1 rho/u/p/e 0.0029/0.0058/0.0037/0.0075; wave offsets from the
// exact profile's crossings, in local particle spacings: shock 0.97, contact -0.63, rarefaction head
// -1.7, tail 1.4 (the fan's edges are rounded over about one kernel support). Before the equal-mass
// setup and the Monaghan (1997) viscosity the tube blew up at t = 0.005 (its first light particle ejected).
TEST_CASE("Sod 1D runs to t = 0.2 with L1 rho <= 0.005 and the waves in place", "[shock_tube][sod]") {
  const auto s = run("sod_1d.yaml", "1d", {});
  REQUIRE_FALSE(s.is_null());
  INFO(s["final_errors"].dump());
  CHECK(s["status"] == "completed");
  CHECK(s["setup"]["type"] == "equal_mass");
  // 400 + 50 columns; the smoothed jump moves one column's centre across x = 0.
  CHECK(s["setup"]["fluid_left"].get<int>() + s["setup"]["fluid_right"].get<int>() == 450);
  CHECK(s["setup"]["mass_left"].get<double>() == Approx(s["setup"]["mass_right"].get<double>()));
  CHECK(l1(s, "L1_rho") < 0.005);
  CHECK(l1(s, "L1_u") < 0.009);
  CHECK(l1(s, "L1_p") < 0.006);
  CHECK(l1(s, "L1_e") < 0.012);
  const auto& w = s["final_errors"]["waves"];
  // The shock and the contact within one local spacing; the fan's edges, smeared over a kernel
  // support, within 2.5.
  CHECK(std::abs(w["shock"]["offset_local_spacings"].get<double>()) < 1.5);
  CHECK(std::abs(w["contact"]["offset_local_spacings"].get<double>()) < 1.0);
  CHECK(std::abs(w["rarefaction_head"]["offset_local_spacings"].get<double>()) < 2.5);
  CHECK(std::abs(w["rarefaction_tail"]["offset_local_spacings"].get<double>()) < 2.5);
}

// Against the 1D tube at the 2D tube's spacing (2.5e-3 on the dense side; the shipped 1D file has
// half of it). Measured (leapfrog, 2800 + 350 particles): 2D L1 rho/u/p/e 0.0039/0.0058/0.0044/0.0100,
// 1D at 2.5e-3 0.0040/0.0086/0.0053/0.0127: 0.98x, 0.67x, 0.84x, 0.79x. (Against the 1D tube at its
// own 1.25e-3, 0.0023/0.0050/0.0029/0.0069, the 2D one is 1.7x in rho: that is the spacing, first
// order with shocks.) At h0 = 1.0 (m / rho)^(1/2), the 1D value, the 2D rarefaction is under-resolved
// along x (measured L1 rho 0.0058).
TEST_CASE("Sod 2D: L1 errors within 1.5x of the 1D tube's at the same spacing", "[shock_tube][sod]") {
  const auto s1 = run("sod_1d.yaml", "2d-ref", {"discretization.spacing=2.5e-3"});
  const auto s2 = run("sod.yaml", "2d", {});
  REQUIRE_FALSE(s1.is_null());
  REQUIRE_FALSE(s2.is_null());
  INFO("1D " << s1["final_errors"].dump() << "\n2D " << s2["final_errors"].dump());
  CHECK(s2["status"] == "completed");
  for (const char* k : {"L1_rho", "L1_u", "L1_p", "L1_e"}) {
    INFO(k);
    CHECK(l1(s2, k) < 1.5 * l1(s1, k));
  }
  CHECK(l1(s2, "L1_rho") < 0.0075);
  const auto& w = s2["final_errors"]["waves"];
  CHECK(std::abs(w["shock"]["offset_local_spacings"].get<double>()) < 1.5);
  CHECK(std::abs(w["contact"]["offset_local_spacings"].get<double>()) < 1.5);
}

// Hernquist-Katz data, equal spacing (Niedoba 2012, §3). Measured (leapfrog): 2D at h0 = 1.3 dx
// L1 rho/u/p/e 0.0053/0.0049/0.0059/0.0088 against 1D 0.0050/0.0048/0.0055/0.0064. At h0 = 1.0 dx
// (as shipped before) the 2D errors were 0.0149/0.0209/0.0170/0.0264, about 3x the 1D ones.
TEST_CASE("Hernquist-Katz tube: 2D L1 errors within 1.5x of 1D", "[shock_tube][sod]") {
  const auto s1 = run("shock_tube_1d.yaml", "hk1", {});
  const auto s2 = run("shock_tube.yaml", "hk2", {});
  REQUIRE_FALSE(s1.is_null());
  REQUIRE_FALSE(s2.is_null());
  INFO("1D " << s1["final_errors"].dump() << "\n2D " << s2["final_errors"].dump());
  for (const char* k : {"L1_rho", "L1_u", "L1_p", "L1_e"}) {
    INFO(k);
    CHECK(l1(s2, k) < 1.5 * l1(s1, k));
  }
}
