// CI-sized runs of the box cases (taylor_green, hydrostatic, cavity) with error bounds that fail when
// the physics is broken (checked by hand with viscosity off / gravity reversed / lid at rest, see
// README). Each runs in seconds in Release.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "sphmol/config/config.hpp"
#include "sphmol/run/run_case.hpp"

using namespace sphmol;

namespace {
nlohmann::json run(const std::string& file, const std::vector<std::string>& overrides) {
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/" + file, overrides);
  RunOptions opt;
  opt.write_files = false;
  return run_case(c, opt);
}
}  // namespace

TEST_CASE("taylor_green: early viscous decay at 30 x 30", "[integration][taylor_green]") {
  const auto s = run("taylor_green.yaml", {"discretization.particles_across=30", "time.t_end=0.1",
                                           "output.times=[0.02, 0.04, 0.06, 0.08, 0.1]"});
  const auto& f = s["final_errors"];
  INFO(f.dump());
  CHECK(f["decay_rate_rel_error"].get<double>() < 0.2);
  CHECK(f["maxv_rel_error"].get<double>() < 0.01);
  CHECK(f["L1_velocity"].get<double>() < 0.05);
  // Fully periodic, no walls, no body force: the pairwise-antisymmetric forces conserve momentum to
  // round-off (measured |drift| / sum m|v| ~ 3e-17 in both directions).
  const auto& cons = s["conservation"];
  CHECK(cons["periodic_directions"] == nlohmann::json({0, 1}));
  for (const auto& d : cons["momentum_drift_relative"]) CHECK(std::abs(d.get<double>()) < 1e-12);
}

TEST_CASE("hydrostatic: pressure and drift stay bounded (coarse, 4 s)", "[integration][hydrostatic]") {
  const auto s = run("hydrostatic.yaml", {"discretization.particles_across=20", "time.dt=5e-4", "time.t_end=4",
                                          "output.times=[2, 3, 4]"});
  const auto& f = s["final_errors"];
  INFO(f.dump());
  CHECK(f["settled_outputs"].get<int>() == 3);
  CHECK(f["p_rms"].get<double>() < 0.1);
  CHECK(f["max_drift"].get<double>() < 2.0);
}

TEST_CASE("cavity: centre lines approach Ghia et al. (20 x 20, t = 3 s)", "[integration][cavity]") {
  const auto s = run("cavity.yaml", {"discretization.particles_across=20", "time.dt=1.2e-3", "time.t_end=3",
                                     "output.times=[3]"});
  REQUIRE(s["compared"].get<bool>());
  const auto& f = s["final_errors"];
  INFO(f.dump());
  CHECK(f["u_rms"].get<double>() < 0.08);
  CHECK(f["v_rms"].get<double>() < 0.08);
}
