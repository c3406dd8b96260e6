// The three-dimensional cases end to end with their shipped verification configs: the square-duct
// start-up against the duct series and the decaying ABC flow against its exact decay rate.
#include <catch2/catch.hpp>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/run/run_case.hpp"

using namespace sphmol;

namespace {
nlohmann::json run(const std::string& file, const std::vector<std::string>& overrides = {}) {
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/" + file, overrides);
  RunOptions opt;
  opt.write_files = false;
  return run_case(c, opt);
}
}  // namespace

TEST_CASE("duct (3D): the square-duct start-up matches the Fourier series", "[integration][duct][3d]") {
  const auto s = run("duct_3d.yaml");
  CHECK(s["dimension"] == 3);
  const auto& d = s["duct"];
  // The summary's reference parameters: u_max = 0.29469 g a^2 / nu for the square.
  CHECK(d["u_max"].get<double>() == Approx(0.2946854 * 2e-4 * 0.25e-6 / 1e-6).epsilon(1e-6));
  const auto& f = s["final_errors"];
  INFO(f.dump());
  // Measured with the shipped settings (16 across, t = 2 a^2/nu, the Morris viscosity normalised by its
  // second moment): e_rms 0.0083, e_max 0.0086. Uncorrected it was 0.0149 / 0.0210 here (the lattice
  // moment of 0.985 makes the viscosity 1.5 % low at any resolution), which fails these bounds.
  CHECK(f["e_rms"].get<double>() <= 0.01);
  CHECK(f["e_max"].get<double>() <= 0.012);
  // No secondary flow in a straight duct at this Reynolds number.
  CHECK(f["e_cross"].get<double>() < 0.01);
}

TEST_CASE("duct (3D): the corrected Laplacian converges at second order in the spacing", "[integration][duct][3d]") {
  // 12 and 16 across over the same 8 spacings of periodic length. Measured: e_rms 0.0144 and 0.0083,
  // order 1.9. Uncorrected the error stalls at a 1.3 % fast centre speed (0.0149 at 16, 0.0105 at 24,
  // 0.0090 at 32 across: order 0.9 from 16 to 24 and 0.5 from 24 to 32).
  const auto coarse = run("duct_3d.yaml", {"discretization.particles_across=12", "geometry.length=6.666666666666667e-4"});
  const auto fine = run("duct_3d.yaml");
  const double e12 = coarse["final_errors"]["e_rms"].get<double>(), e16 = fine["final_errors"]["e_rms"].get<double>();
  INFO("e_rms " << e12 << " at 12 across, " << e16 << " at 16");
  CHECK(std::log(e12 / e16) / std::log(16.0 / 12.0) > 1.6);
}

TEST_CASE("beltrami (3D): the ABC flow decays at nu k^2", "[integration][beltrami][3d]") {
  const auto s = run("beltrami_3d.yaml");
  CHECK(s["dimension"] == 3);
  const auto& f = s["final_errors"];
  INFO(f.dump());
  // Measured with the shipped settings: decay_rate within 1.2 %, L1_velocity 0.086.
  CHECK(f["decay_rate_exact"].get<double>() == Approx(0.1 * 4.0 * M_PI * M_PI).epsilon(1e-12));
  CHECK(std::abs(f["decay_rate"].get<double>() / f["decay_rate_exact"].get<double>() - 1.0) <= 0.05);
  CHECK(f["L1_velocity"].get<double>() < 0.15);
  // Fully periodic, no walls, no body force: momentum is conserved to round-off.
  for (const auto& m : s["conservation"]["momentum_drift_relative"]) CHECK(std::abs(m.get<double>()) < 1e-10);
}
