// A flow driven along -x (negative plate speed, body force or lid speed) is the mirror image of the
// one driven along +x: each case must report the same errors for both. Short coarse runs.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/run/run_case.hpp"
#include "run_helpers.hpp"
#include "in_process_run.hpp"

using namespace sphmol;

namespace {

nlohmann::json run(const std::string& file, const std::vector<std::string>& overrides) {
  return in_process::run_verification(file, overrides);
}

// The same value to a relative `tolerance`: the mirrored run sums in another order.
void check_same(const nlohmann::json& plus, const nlohmann::json& minus, const std::string& key, double tolerance = 1e-9) {
  INFO(key << ": +" << plus[key] << " -" << minus[key]);
  REQUIRE(plus[key].is_number());
  REQUIRE(minus[key].is_number());
  const double a = plus[key], b = minus[key];
  CHECK(std::abs(a - b) <= tolerance * std::abs(a) + 1e-15);
}

}  // namespace

TEST_CASE("couette: a negative plate speed gives the mirrored run's e_max and e_rms", "[integration][couette]") {
  const std::vector<std::string> common = {"discretization.particles_across=20", "time.integrator=leapfrog", "time.t_end=0.05",
                                           "output.times=[0.05]"};
  auto with = [&](const std::string& v) {
    auto o = common;
    o.push_back("geometry.wall_velocity=" + v);
    return run("couette.yaml", o)["final_errors"];
  };
  const auto plus = with("2.5e-5"), minus = with("-2.5e-5");
  CHECK(plus["e_max"].get<double>() > 0.0);
  for (const char* k : {"e_max", "e_rms", "e_signed"}) check_same(plus, minus, k);
}

TEST_CASE("poiseuille: a negative body force gives the mirrored run's e_max and e_rms", "[integration][poiseuille]") {
  const std::vector<std::string> common = {"discretization.particles_across=20", "time.integrator=leapfrog", "time.t_end=0.05",
                                           "output.times=[0.05]"};
  auto with = [&](const std::string& g) {
    auto o = common;
    o.push_back("fluid.body_force=[" + g + ", 0]");
    return run("poiseuille.yaml", o)["final_errors"];
  };
  const auto plus = with("2e-4"), minus = with("-2e-4");
  CHECK(plus["e_max"].get<double>() > 0.0);
  for (const char* k : {"e_max", "e_rms", "e_signed"}) check_same(plus, minus, k);
}

TEST_CASE("duct: a negative body force gives positive errors the mirrored run's and a peak along the flow", "[integration][duct][3d]") {
  const std::vector<std::string> common = {"discretization.particles_across=8", "geometry.length=1e-3", "time.t_end=0.05",
                                           "output.times=[0.025]", "output.plots=false"};
  auto with = [&](const std::string& g) {
    auto o = common;
    o.push_back("fluid.body_force=[" + g + ", 0, 0]");
    return run("duct_3d.yaml", o)["final_errors"];
  };
  const auto plus = with("2e-4"), minus = with("-2e-4");
  CHECK(plus["e_rms"].get<double>() > 0.0);
  for (const char* k : {"e_rms", "e_max"}) check_same(plus, minus, k);
  check_same(plus, minus, "e_cross", 1e-6);  // round-off of u: 1.8e-8 relative measured
  // peak.csv: u_x of the fastest particle along -x, the +g run's peaks with the sign of the flow.
  namespace rh = run_helpers;
  const auto dir = rh::scratch("duct-minus");
  std::string args = "--config '" + std::string(SPHMOL_SOURCE_DIR) + "/verification/duct_3d.yaml' -q --output '" +
                     (dir / "out").string() + "' --set 'fluid.body_force=[-2e-4, 0, 0]'";
  for (const auto& o : common) args += " --set '" + o + "'";
  const auto r = rh::sph_mol(args, dir / "err.txt");
  REQUIRE(r.code == 0);
  std::istringstream peak(rh::slurp(dir / "out" / "peak.csv"));
  std::string line;
  std::getline(peak, line);
  int rows = 0;
  while (std::getline(peak, line)) {
    INFO(line);
    double t = 0, sph = 0, exact = 0;
    char c1 = 0, c2 = 0;
    std::istringstream(line) >> t >> c1 >> sph >> c2 >> exact;
    CHECK(sph < 0.0);
    CHECK(exact < 0.0);
    CHECK(std::abs(sph - exact) < 0.05 * std::abs(exact));
    ++rows;
  }
  CHECK(rows == 2);
  std::filesystem::remove_all(dir);
}

TEST_CASE("cavity: a lid along -x gives the mirrored run's centre-line errors (20 x 20, t = 0.5 s)", "[integration][cavity]") {
  const std::vector<std::string> common = {"discretization.particles_across=20", "time.t_end=0.5", "output.times=[0.5]"};
  auto with = [&](const std::string& u) {
    auto o = common;
    o.push_back("geometry.wall_velocity=" + u);
    return run("cavity.yaml", o)["final_errors"];
  };
  const auto plus = with("1"), minus = with("-1");
  // Measured: the two runs agree to 2e-6 relative (the particles' sums in mirrored order).
  for (const char* k : {"u_rms", "u_max", "v_rms", "v_max"}) check_same(plus, minus, k, 1e-4);
}
