// Runs sph-mol on the shock tube (verification/shock_tube.yaml, full 320 x 10 resolution, leapfrog)
// and checks the L1 errors and wave positions against the exact Riemann solution; checks that the
// state holds only what each scene needs.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "in_process_run.hpp"

namespace {

// SPHMOL_SOURCE_DIR, not __FILE__: with CCACHE_BASEDIR the latter is relative to the build directory.
const std::string source_dir = SPHMOL_SOURCE_DIR;

// Runs the binary; returns the summary, or null when the run failed.
nlohmann::json run(const std::string& config, const std::string& tag, const std::string& sets) {
  const std::string out = (std::filesystem::temp_directory_path() / ("sphmol-it-" + tag)).string();
  std::filesystem::remove_all(out);
  const std::string cmd = std::string(SPHMOL_BINARY) + " --config " + source_dir + "/" + config + " --output " + out +
                          " " + sets + " > " + out + ".log 2>&1";
  if (std::system(cmd.c_str()) != 0) return nullptr;
  std::ifstream in(out + "/summary.json");
  return nlohmann::json::parse(in);
}

// Bounds measured at 320 x 10 with leapfrog (CFL step), docs/verification.md: free-slip ghost walls,
// h0 = 1.3 dx (the shipped file) L1_rho 0.0053, L1_u 0.0049, L1_p 0.0059, L1_e 0.0088 (at h0 = 1.0 dx,
// as shipped before, 0.0149/0.0211/0.0170/0.0262: these bounds fail there); waves within 0.005 of the
// exact positions except the rarefaction tail, read at 95 % of u* inside the fan (0.012 from its
// exact edge). Bounds at about 1.5x the measured errors.
// Conservation with closed ends (fixed wall particles holding the initial states) and, in 2D,
// periodic y. The total energy sum m (v^2/2 + e) is conserved (the artificial-viscosity work is put
// into e, Niedoba 2012, eq 2.72; the walls do no work): measured relative drift at t = 0.2 with leapfrog
// -2.5e-6 (2D) and -6.0e-6 (1D); bound 1e-4. The x-momentum is not conserved: the end walls push
// with the initial pressures, so P_x(t) = (p_L - p_R) A t while no wave reaches them (A = tube width
// in 2D, 1 in 1D); measured within 0.3 %. In 2D with periodic y the y-momentum drifts at round-off;
// with the free-slip ghost walls (the shipped file) the walls push on the fluid, evenly only for a
// y-symmetric particle set: measured relative y drift 1.05e-3 (absolute 4.3e-6 against an x drift of
// 4.1e-3), bound 1e-2.
void check_conservation(const nlohmann::json& s, double area) {
  const auto& c = s["conservation"];
  INFO("conservation: " << c["total_energy"].dump() << ", momentum drift " << c["momentum_drift"].dump());
  CHECK(std::abs(c["total_energy_drift_relative"].get<double>()) < 1e-4);
  const double t = c["times"].back().get<double>() - c["times"].front().get<double>();
  const double expected_px = (1.0 - 0.1795) * area * t;
  CHECK(c["momentum_drift"][0].get<double>() == Approx(expected_px).epsilon(0.02));
  if (c["momentum_drift"].size() == 2) {
    const bool periodic_y = c["periodic_directions"] == nlohmann::json({1});
    CHECK(std::abs(c["momentum_drift_relative"][1].get<double>()) < (periodic_y ? 1e-12 : 1e-2));
  }
}

bool within_bounds(const nlohmann::json& s, bool report) {
  if (s.is_null()) return false;
  const auto& e = s["final_errors"];
  bool ok = e["L1_rho"].get<double>() < 0.008 && e["L1_u"].get<double>() < 0.0075 && e["L1_p"].get<double>() < 0.009 &&
            e["L1_e"].get<double>() < 0.013;
  const double tol[] = {0.01, 0.01, 0.01, 0.02};
  const char* names[] = {"shock", "contact", "rarefaction_head", "rarefaction_tail"};
  for (int k = 0; k < 4; ++k) {
    const auto& w = e["waves"][names[k]];
    if (w["sph"].is_null()) return false;
    const double d = std::abs(w["sph"].get<double>() - w["exact"].get<double>());
    if (report) UNSCOPED_INFO(names[k] << ": |sph - exact| = " << d);
    ok = ok && d < tol[k];
  }
  return ok;
}

}  // namespace

TEST_CASE("shock tube 320x10: L1 errors and wave positions against the exact Riemann solution", "[shock_tube]") {
  const auto s = run("verification/shock_tube.yaml", "shock", "--set time.integrator=leapfrog");
  REQUIRE_FALSE(s.is_null());
  INFO(s["final_errors"].dump());
  CHECK(within_bounds(s, true));
  CHECK(s["state_fields"] == nlohmann::json({"position", "velocity", "density", "energy", "smoothing_length"}));
  CHECK(s["particles"]["fluid"] == 3200);
  CHECK(s["y_walls"] == "ghost (mirror) walls at y = 0 and y = W");
  const auto& e = s["final_errors"];
  CHECK(e["L1_mid_rho"].get<double>() < 0.008);
  CHECK(e["L1_mid_u"].get<double>() < 0.0075);
  CHECK(e["L1_mid_p"].get<double>() < 0.009);
  CHECK(e["L1_mid_e"].get<double>() < 0.013);
  check_conservation(s, 0.025);
}

// The virtual-particle variant of Niedoba 2012, §3.3 (verification/shock_tube_virtual.yaml). Measured
// (leapfrog): L1_rho 0.046, L1_u 0.086, L1_p 0.054, L1_e 0.094 (mid-line 0.036/0.044/0.045/0.066);
// shock at 0.281 (exact 0.297), rarefaction head -0.227 (exact -0.237); contact and rarefaction tail
// not resolved by the crossing detector. As in the thesis (Figs 3.5-3.8) it is clearly worse than the
// ghost walls: it misses the ghost bounds. Bounds here at ~1.5x the measured errors.
TEST_CASE("shock tube with virtual particles (Niedoba 2012, §3.3): runs, worse than ghost walls", "[shock_tube]") {
  const auto s = run("verification/shock_tube_virtual.yaml", "shock-virtual", "--set time.integrator=leapfrog");
  REQUIRE_FALSE(s.is_null());
  INFO(s["final_errors"].dump());
  const auto& e = s["final_errors"];
  CHECK(e["L1_rho"].get<double>() < 0.07);
  CHECK(e["L1_u"].get<double>() < 0.13);
  CHECK(e["L1_p"].get<double>() < 0.08);
  CHECK(e["L1_e"].get<double>() < 0.14);
  CHECK(std::abs(e["waves"]["shock"]["sph"].get<double>() - e["waves"]["shock"]["exact"].get<double>()) < 0.03);
  CHECK_FALSE(within_bounds(s, false));
}

TEST_CASE("shock tube with no-slip ghost walls: the inviscid gas slips as with free slip", "[shock_tube][ghost]") {
  // The no-slip images' velocity 2 v_w - v entered the continuity, pressure and energy sums, as if the
  // gas did not slip along the walls: the run blew up at t = 0.026 s ("density <= 0"). It now enters
  // the viscous terms only, which the gas has none of: the run is the free-slip run, bit for bit.
  const std::vector<std::string> set{"discretization.spacing=0.005", "time.t_end=0.05", "output.times=[0.05]"};
  auto no_slip = set;
  no_slip.push_back("discretization.wall_slip=no_slip");
  const auto c = sphmol::load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/shock_tube.yaml", no_slip);
  REQUIRE(c.notices.size() >= 1);
  CHECK_THAT(c.notices.back(), Catch::Contains("discretization.wall_slip: no_slip has no effect"));
  const nlohmann::json a = in_process::run_verification("shock_tube.yaml", no_slip);
  const nlohmann::json b = in_process::run_verification("shock_tube.yaml", set);
  REQUIRE(a["status"] == "completed");
  CHECK(a["final_errors"] == b["final_errors"]);
  CHECK(a["steps"] == b["steps"]);
}

TEST_CASE("shock tube without artificial viscosity misses the bounds (or fails)", "[shock_tube]") {
  const auto s = run("verification/shock_tube.yaml", "shock-noav",
                     "--set time.integrator=leapfrog --set discretization.artificial_viscosity.alpha=0 "
                     "--set discretization.artificial_viscosity.beta=0");
  CHECK_FALSE(within_bounds(s, false));
}

TEST_CASE("state fields: Couette integrates positions and velocities only", "[state]") {
  const auto s = run("verification/couette.yaml", "couette-fields", "--set time.t_end=0.01 --set output.times=[0.01]");
  REQUIRE_FALSE(s.is_null());
  CHECK(s["state_fields"] == nlohmann::json({"position", "velocity"}));
}

TEST_CASE("shock tube 1D variant: L1 errors and wave positions", "[shock_tube]") {
  const auto s = run("verification/shock_tube_1d.yaml", "shock-1d", "--set time.integrator=leapfrog");
  REQUIRE_FALSE(s.is_null());
  INFO(s["final_errors"].dump());
  // Measured: L1_rho 0.0050, L1_u 0.0048, L1_p 0.0055, L1_e 0.0064; waves within 0.0053.
  const auto& e = s["final_errors"];
  CHECK(e["L1_rho"].get<double>() < 0.0075);
  CHECK(e["L1_u"].get<double>() < 0.0075);
  CHECK(e["L1_p"].get<double>() < 0.0085);
  CHECK(e["L1_e"].get<double>() < 0.01);
  for (const char* w : {"shock", "contact", "rarefaction_head", "rarefaction_tail"})
    CHECK(std::abs(e["waves"][w]["sph"].get<double>() - e["waves"][w]["exact"].get<double>()) < 0.01);
  CHECK(s["dimension"] == 1);
  check_conservation(s, 1.0);
}
