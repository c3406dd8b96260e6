// Blow-up detection end to end (exit code 3, status and cause in summary.json, last good state),
// conservation diagnostics, and the new integrators on a short Couette run.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "sphmol/config/config.hpp"
#include "sphmol/run/run_case.hpp"

using namespace sphmol;

namespace {
const std::string couette = SPHMOL_SOURCE_DIR "/verification/couette.yaml";
}

TEST_CASE("an unstable run ends cleanly as blown_up with exit code 3", "[integration][blowup]") {
  // Leapfrog with a fixed step 40x the viscous stability limit (0.125 h^2/nu ~ 5e-4 s at 20 across).
  // On 1 and 2 threads: the health check runs in parallel (run/health_check.hpp) and must name the
  // same particle and cause, and keep the same last good state.
  nlohmann::json first;
  for (const int threads : {1, 2}) {
    INFO("threads " << threads);
    const std::string out = "reports/blow_up_" + std::to_string(threads);
    std::filesystem::remove_all(out);
    std::filesystem::create_directories("reports");  // the stderr redirection below needs it
    const std::string cmd = std::string(SPHMOL_BINARY) + " --threads " + std::to_string(threads) + " --config " + couette +
                            " --output " + out +
                            " --set discretization.particles_across=20 --set time.integrator=leapfrog --set time.dt=2e-2"
                            " --set time.t_end=5 --set output.times=[5] 2>" + out + ".log";
    const int rc = std::system(cmd.c_str());
    REQUIRE(WIFEXITED(rc));
    CHECK(WEXITSTATUS(rc) == 3);
    std::ifstream f(out + "/summary.json");
    REQUIRE(f.good());
    const auto s = nlohmann::json::parse(f);
    CHECK(s["status"] == "blown_up");
    INFO(s["blow_up"].dump());
    CHECK(s["blow_up"]["t"].get<double>() < 5.0);
    CHECK_FALSE(s["blow_up"]["cause"].get<std::string>().empty());
    CHECK(std::filesystem::exists(out + "/last_good_state.csv"));
    std::ifstream g(out + "/last_good_state.csv");
    const std::string state((std::istreambuf_iterator<char>(g)), std::istreambuf_iterator<char>());
    CHECK(state.size() > 100);
    if (threads == 1) {
      first = s["blow_up"];
      first["state"] = state;
    } else {
      CHECK(s["blow_up"]["message"] == first["message"]);
      CHECK(s["blow_up"]["last_good_t"] == first["last_good_t"]);
      CHECK(state == first["state"].get<std::string>());
    }
  }
}

TEST_CASE("conservation: Couette y-momentum stays near 0 and a stable run reports status completed", "[integration][conservation]") {
  // x-momentum is not conserved (the moving plate drives the flow); y-momentum has no source on
  // average (the wall pressure forces on both sides balance), so its drift must stay tiny compared
  // with the x-momentum scale M v0.
  Config c = load_config(couette, {"discretization.particles_across=20", "time.t_end=0.1", "output.times=[0.05,0.1]"});
  RunOptions o;
  o.write_files = false;
  const auto s = run_case(c, o);
  CHECK(s["status"] == "completed");
  const auto& cons = s["conservation"];
  REQUIRE(cons["times"].size() == 3);
  const double M = cons["fluid_mass"].get<double>(), v0 = c.geometry.wall_velocity;
  const double px = cons["momentum"].back()[0].get<double>();
  const double py_drift = cons["momentum_drift"][1].get<double>();
  INFO("Px = " << px << ", Py drift = " << py_drift << ", M v0 = " << M * v0);
  CHECK(px > 0.01 * M * v0);  // the plate has set the fluid moving
  CHECK(std::abs(py_drift) < 1e-4 * M * v0);
  CHECK(cons["kinetic_energy"].back().get<double>() > 0.0);
}

TEST_CASE("leapfrog_kdk and cvode_adams agree with ARKODE on a short Couette run", "[integration][time]") {
  double e_ref = 0.0;
  for (const char* integ : {"arkode_erk", "leapfrog_kdk", "cvode_adams"}) {
    Config c = load_config(couette, {"discretization.particles_across=20", "time.t_end=0.05", "output.times=[0.05]",
                                     std::string("time.integrator=") + integ});
    RunOptions o;
    o.write_files = false;
    const auto s = run_case(c, o);
    const double e = s["final_errors"]["e_rms"].get<double>();
    INFO(integ << ": e_rms " << e);
    CHECK(s["status"] == "completed");
    CHECK(s["steps"].get<long>() > 0);
    CHECK(s["rhs_evals"].get<long>() >= s["steps"].get<long>());
    if (std::string(integ) == "arkode_erk") e_ref = e;
    else CHECK(std::abs(e - e_ref) < 0.05 * e_ref);
  }
}
