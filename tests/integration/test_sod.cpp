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

// Runs the binary on a shipped config with `sets` (each a --set value); the summary, or null when the
// run failed (with `failed_too`: the summary a failed run wrote, e.g. a blown-up one, or null).
nlohmann::json run(const std::string& config, const std::string& tag, const std::vector<std::string>& sets,
                   bool failed_too = false) {
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
  if (r.code != 0 && !(failed_too && std::filesystem::exists(out / "summary.json"))) return nullptr;
  std::ifstream in(out / "summary.json");
  return nlohmann::json::parse(in);
}

double l1(const nlohmann::json& s, const char* key) { return s["final_errors"][key].get<double>(); }

}  // namespace

// Measured (leapfrog, 450 particles, jump smoothed over a quarter spacing; 2026-12-07): L1 rho/u/p/e
// 0.0029/0.0049/0.0036/0.0065; wave offsets from the exact profile's crossings, in local particle
// spacings: shock -0.26 (the middle of its density jump; the velocity's crossing of u*/2 0.61),
// contact 0.46, rarefaction head -0.68, tail 0.44. With the jump smoothed over
// one spacing (the default before) the head led by 1.56 and the tail lagged by 1.42: the smoothed
// start spreads the fan before t = 0. Before the equal-mass setup and the Monaghan (1997) viscosity
// the tube blew up at t = 0.005 (its first light particle ejected).
TEST_CASE("Sod 1D runs to t = 0.2 with L1 rho <= 0.005 and every wave within one local spacing", "[shock_tube][sod]") {
  const auto s = run("sod_1d.yaml", "1d", {});
  REQUIRE_FALSE(s.is_null());
  INFO(s["final_errors"].dump());
  CHECK(s["status"] == "completed");
  CHECK(s["setup"]["type"] == "equal_mass");
  CHECK(s["setup"]["fluid_left"].get<int>() + s["setup"]["fluid_right"].get<int>() == 450);
  CHECK(s["setup"]["mass_left"].get<double>() == Approx(s["setup"]["mass_right"].get<double>()));
  CHECK(l1(s, "L1_rho") < 0.005);
  CHECK(l1(s, "L1_u") < 0.006);
  CHECK(l1(s, "L1_p") < 0.005);
  CHECK(l1(s, "L1_e") < 0.009);
  const auto& w = s["final_errors"]["waves"];
  for (const char* k : {"shock", "contact", "rarefaction_head", "rarefaction_tail"}) {
    INFO(k);
    CHECK(std::abs(w[k]["offset_local_spacings"].get<double>()) < 1.0);
  }
}

// The same at half and twice the spacing (the default smoothing, not the shipped file's value):
// measured (2026-12-07) at 2.5e-3 shock -0.01, contact 0.50, head -0.80, tail 0.46; at 6.25e-4 -0.59,
// 0.29, -0.44, 0.50 (the shock's velocity crossing 0.86 / 0.28).
TEST_CASE("Sod 1D: the waves stay within one local spacing at twice and half the spacing", "[shock_tube][sod]") {
  for (const char* dx : {"2.5e-3", "6.25e-4"}) {
    const auto s = run("sod_1d.yaml", std::string("1d-") + dx, {std::string("discretization.spacing=") + dx, "shock_tube.smoothing=0.25"});
    REQUIRE_FALSE(s.is_null());
    INFO(dx << " " << s["final_errors"].dump());
    const auto& w = s["final_errors"]["waves"];
    for (const char* k : {"shock", "contact", "rarefaction_head", "rarefaction_tail"}) {
      INFO(k);
      CHECK(std::abs(w[k]["offset_local_spacings"].get<double>()) < 1.0);
    }
  }
}

// Against the 1D tube at the 2D tube's spacing (2.5e-3 on the dense side; the shipped 1D file has
// half of it). Measured (leapfrog, 2800 + 350 particles, continuity with volume weights, the integral
// approach's gradients, the jump smoothed over half a spacing; 2026-12-07): 2D L1 rho/u/p/e
// 0.0022/0.0057/0.0025/0.0076, 1D at 2.5e-3 (its jump smoothed over a quarter spacing)
// 0.0055/0.0104/0.0069/0.0127; wave offsets in local spacings shock 0.16 (the middle of its density
// jump; the velocity's crossing of u*/2 1.47), contact 0.17, fan head 0.38, tail 0.71. With the kernel
// gradient (the file before): 0.0031/0.0054/0.0039/0.0080, shock -0.59, contact 0.27, head -0.60, tail
// -0.59. With the mass-weighted continuity (the 1D file's) the start had to be smoothed over one
// spacing: 0.0039/0.0058/0.0044/0.0100, head -2.09. At h0 = 1.0 (m / rho)^(1/2), the 1D value, the 2D
// rarefaction is under-resolved along x.
TEST_CASE("Sod 2D: L1 errors within 1.5x of the 1D tube's at the same spacing, every wave within one local spacing",
          "[shock_tube][sod]") {
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
  CHECK(l1(s2, "L1_rho") < 0.003);
  const auto& w = s2["final_errors"]["waves"];
  for (const char* k : {"shock", "contact", "rarefaction_head", "rarefaction_tail"}) {
    INFO(k);
    CHECK(std::abs(w[k]["offset_local_spacings"].get<double>()) < 1.0);
  }
}

// Twice the spacing (5e-3: 100 x 7 dense, 35 x 2 light), smoothed as shipped and sharp (smoothing 0).
// With the mass-weighted continuity the sharp start's first light column, pushed away from the dense
// gas, loses density 8x faster than -rho div v and is ejected (blown up at t = 0.0088; smoothed over
// half a spacing at t = 0.086). With volume weights (Colagrossi & Landrini 2003) it runs. Measured
// offsets in local spacings (shock, contact, fan head, tail; 2026-12-07): smoothed 0.30, 0.09, 0.07,
// 0.63 (L1 rho 0.0044), sharp 0.47, 0.36, 0.29, 0.51 (0.0060). With the kernel gradient the smoothed
// start put the shock's velocity crossing 1.44 ahead and the sharp one 1.92 (two light rows across).
TEST_CASE("Sod 2D at twice the spacing: every wave within one local spacing, a sharp start runs with the "
          "volume-weighted continuity, not with the mass-weighted one",
          "[shock_tube][sod]") {
  const auto coarse = run("sod.yaml", "2d-coarse", {"discretization.spacing=5e-3"});
  REQUIRE_FALSE(coarse.is_null());
  INFO(coarse["final_errors"].dump());
  CHECK(coarse["status"] == "completed");
  CHECK(l1(coarse, "L1_rho") < 0.006);
  for (const char* k : {"shock", "contact", "rarefaction_head", "rarefaction_tail"}) {
    INFO(k);
    CHECK(std::abs(coarse["final_errors"]["waves"][k]["offset_local_spacings"].get<double>()) < 1.0);
  }
  const std::vector<std::string> sharp = {"shock_tube.smoothing=0", "discretization.spacing=5e-3"};
  auto with = [&](const char* form) {
    auto sets = sharp;
    sets.push_back(std::string("discretization.continuity=") + form);
    return sets;
  };
  const auto v = run("sod.yaml", "2d-sharp-volume", with("volume"));
  REQUIRE_FALSE(v.is_null());
  INFO(v["final_errors"].dump());
  CHECK(v["status"] == "completed");
  CHECK(l1(v, "L1_rho") < 0.008);
  const auto& w = v["final_errors"]["waves"];
  for (const char* k : {"shock", "contact", "rarefaction_head", "rarefaction_tail"}) {
    INFO(k);
    CHECK(std::abs(w[k]["offset_local_spacings"].get<double>()) < 1.0);
  }
  const auto m = run("sod.yaml", "2d-sharp-mass", with("mass"), true);
  REQUIRE_FALSE(m.is_null());
  CHECK(m["status"] == "blown_up");
}

// Half the shipped spacing (1.25e-3) in a tube of half the width (0.0175: 14 dense rows, 5 light; with
// mirror walls the errors and offsets are those of the full width to the digits printed): the shipped
// tube run twice as long in units of the spacing. Measured (2026-12-07, 661 steps, about 70 s on one
// thread): L1 rho/u/p/e 0.0012/0.0033/0.0014/0.0040; shock 0.15, contact 0.16, fan head 0.56, tail 0.73.
// With the kernel gradient (the file before, --set discretization.momentum=symmetric_117): 0.0029/
// 0.0043/0.0035/0.0059, shock -1.23 (its plateau 2 % dense), fan tail -1.81: L1 rho did not converge
// below 2.5e-3 (0.0031) and the tail moved away (-0.59 at 2.5e-3).
TEST_CASE("Sod 2D at half the spacing: L1 rho converges and every wave stays within one local spacing",
          "[shock_tube][sod]") {
  const auto s = run("sod.yaml", "2d-fine", {"discretization.spacing=1.25e-3", "geometry.tube_width=0.0175"});
  REQUIRE_FALSE(s.is_null());
  INFO(s["final_errors"].dump());
  CHECK(s["status"] == "completed");
  CHECK(l1(s, "L1_rho") < 0.0018);
  CHECK(l1(s, "L1_p") < 0.002);
  for (const char* k : {"shock", "contact", "rarefaction_head", "rarefaction_tail"}) {
    INFO(k);
    CHECK(std::abs(s["final_errors"]["waves"][k]["offset_local_spacings"].get<double>()) < 1.0);
  }
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

TEST_CASE("sod: the mirrored tube reads the mirrored waves", "[sod][shock_tube]") {
  // High pressure on the right: the same problem seen from the other side. Every wave is read where
  // Sod's is, negated, and compared with the exact wave of the same kind (a left-moving shock, a
  // right-facing fan). Coarse and short: 200 + 25 particles to t = 0.1.
  const std::vector<std::string> common = {"discretization.spacing=2.5e-3", "time.t_end=0.1", "output.times=[]"};
  std::vector<std::string> mirror = common;
  mirror.push_back("shock_tube.left={density: 0.125, pressure: 0.1}");
  mirror.push_back("shock_tube.right={density: 1.0, pressure: 1.0}");
  const auto s = run("sod_1d.yaml", "mirror-a", common), m = run("sod_1d.yaml", "mirror-b", mirror);
  REQUIRE(!s.is_null());
  REQUIRE(!m.is_null());
  CHECK(m["exact"]["wave_pattern"] == nlohmann::json({{"left", "shock"}, {"right", "rarefaction"}}));
  const auto& ws = s["final_errors"]["waves"];
  const auto& wm = m["final_errors"]["waves"];
  for (const char* k : {"shock", "shock_velocity", "contact", "rarefaction_head", "rarefaction_tail"}) {
    INFO(k);
    REQUIRE(wm[k]["sph"].is_number());
    CHECK(wm[k]["sph"].get<double>() == Approx(-ws[k]["sph"].get<double>()).margin(1e-9));
    CHECK(wm[k]["exact"].get<double>() == Approx(-ws[k]["exact"].get<double>()).margin(1e-12));
    CHECK(wm[k]["offset_local_spacings"].get<double>() == Approx(-ws[k]["offset_local_spacings"].get<double>()).margin(1e-6));
  }
  CHECK(wm["shock"]["side"] == "left");
  CHECK(wm["rarefaction_head"]["side"] == "right");
  CHECK(l1(m, "L1_rho") == Approx(l1(s, "L1_rho")).epsilon(1e-9));
}
