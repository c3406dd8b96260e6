// Outflow end to end (run/outflow.hpp): fluid that leaves the domain through an open face is taken
// out and the run goes on, with the summary's "outflow" and a warning; beyond
// health.max_outflow_fraction the run ends as blown up; a restart from a checkpoint written after an
// exit continues with the particle still out, bit for bit with the leapfrog; the dam break run past
// its run-up completes.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "run_helpers.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/io/double_codec.hpp"
#include "sphmol/run/run_case.hpp"
#include "shot_scene.hpp"

using namespace sphmol;
using namespace run_helpers;

namespace {

using sphmol::testing::shot_scene;

std::size_t outside(const std::vector<double>& y, std::size_t n, std::size_t& which) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (y[i] > 0.34 || y[i] < -0.02 || y[n + i] > 0.42 || y[n + i] < -0.02) {
      ++count;
      which = i;
    }
  return count;
}

}  // namespace

TEST_CASE("outflow: a particle shot through an open face is taken out and the run goes on", "[integration][outflow]") {
  // Every integrator starts again after the exit (Integrator::restart); the IMEX ones need a viscous term.
  for (const std::string integrator : {"leapfrog", "leapfrog_kdk", "arkode_erk", "cvode_adams", "leapfrog_imex", "arkode_imex"}) {
    DYNAMIC_SECTION(integrator) {
      std::vector<std::string> set = {"time.integrator=" + integrator};
      if (integrator.find("imex") != std::string::npos)
        set.insert(set.end(), {"fluid.kinematic_viscosity=1e-4", "discretization.viscosity=morris", "discretization.wall_model=prescribed"});
      const Config c = shot_scene(set);
      RunOptions opt;
      opt.write_files = false;
      std::vector<double> y;
      opt.final_state = &y;
      const auto s = run_case(c, opt);
      INFO(s.dump().substr(0, 2000));
      REQUIRE(s["status"] == "completed");
      const auto& o = s["outflow"];
      CHECK(o["particles"] == 1);
      CHECK(o["mass_fraction"].get<double>() == Approx(1.0 / 101.0));
      CHECK(o["t_first"].get<double>() > 0.0);
      CHECK(o["t_first"].get<double>() < 0.02);
      bool warned = false;
      for (const auto& w : s["warnings"]) warned = warned || w.get<std::string>().rfind("outflow: 1 fluid particle(s)", 0) == 0;
      CHECK(warned);
      // It stays frozen where it left: just past the face (3 m/s for one step at most), at rest.
      const std::size_t n = s["particles"]["fluid"];
      REQUIRE(y.size() >= 4 * n);
      std::size_t p = 0;
      REQUIRE(outside(y, n, p) == 1);
      CHECK(p == o["first_particle"].get<std::size_t>());
      CHECK(y[p] > 0.34);
      CHECK(y[p] < 0.35);
      CHECK(y[2 * n + p] == 0.0);
      CHECK(y[3 * n + p] == 0.0);
      // The scene's mass is all still in the state.
      CHECK(s["final_errors"]["fluid_mass"].get<double>() == s["conservation"]["fluid_mass"].get<double>());
      CHECK(o["mass"].get<double>() == Approx(s["conservation"]["fluid_mass"].get<double>() / 101.0));
    }
  }
}

TEST_CASE("outflow: beyond health.max_outflow_fraction the run ends as blown up", "[integration][outflow]") {
  const Config c = shot_scene({"health.max_outflow_fraction=0.005"});
  RunOptions opt;
  opt.write_files = false;
  const auto s = run_case(c, opt);
  REQUIRE(s["status"] == "blown_up");
  const std::string cause = s["blow_up"]["cause"];
  CHECK(cause.rfind("outflow: 1 fluid particle(s)", 0) == 0);
  CHECK(s["blow_up"]["t"].get<double>() < 0.02);
}

TEST_CASE("outflow: a restart from a checkpoint after an exit continues with the particle out", "[integration][outflow][restart]") {
  const fs::path dir = scratch("outflow-restart");
  const auto run = [&](const std::string& sub, double t_end, const std::string& restart, std::vector<double>& y) {
    Config c = shot_scene({"output.checkpoint_every=0.05", "time.t_end=" + std::to_string(t_end),
                           "output.directory=" + (dir / sub).string()});
    RunOptions opt;
    opt.final_state = &y;
    opt.restart_from = restart;
    return run_case(c, opt);
  };
  std::vector<double> whole, first, second;
  const auto a = run("whole", 0.1, "", whole);
  REQUIRE(a["status"] == "completed");
  REQUIRE(a["outflow"]["particles"] == 1);
  REQUIRE(run("first", 0.05, "", first)["status"] == "completed");
  const auto b = run("second", 0.1, (dir / "first" / "checkpoint-0.05").string(), second);
  REQUIRE(b["status"] == "completed");
  CHECK(b["restarted_from"]["t"] == 0.05);
  // Taken out again at the restart, from where it sits: the same particle, still out.
  CHECK(b["outflow"]["particles"] == 1);
  CHECK(b["outflow"]["at_start"] == 1);
  CHECK(b["outflow"]["t_first"].is_null());
  CHECK(a["outflow"]["at_start"] == 0);
  CHECK(b["steps"] == a["steps"]);
  REQUIRE(second.size() == whole.size());
  std::size_t differ = 0;
  for (std::size_t k = 0; k < whole.size(); ++k) differ += std::memcmp(&whole[k], &second[k], sizeof(double)) != 0;
  CHECK(differ == 0);
}

TEST_CASE("outflow: the dam break run past its run-up completes (dp = 0.04)", "[integration][outflow][dam_break]") {
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml",
                               {"discretization.spacing=0.04", "time.t_end=2.0", "output.times=[0.5, 1.0, 1.5, 2.0]",
                                "output.plots=false"});
  RunOptions opt;
  opt.write_files = false;
  const auto s = run_case(c, opt);
  INFO(s["outflow"].dump());
  if (s.contains("blow_up")) INFO(s["blow_up"].dump());
  REQUIRE(s["status"] == "completed");
  REQUIRE(s.contains("outflow"));
  CHECK(s["outflow"]["mass_fraction"].get<double>() <= 0.05);
  // The mass stays in the state (particles taken out keep theirs).
  CHECK(s["final_errors"]["mass_change"].get<double>() == 0.0);
  CHECK(s["final_errors"]["wall_penetrations"].get<long>() == 0);
}
