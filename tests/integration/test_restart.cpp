// Checkpoint/restart through the command line: a run stopped at t = 0.05 and continued with
// --restart to 0.1 ends in the same state as a run straight to 0.1 — bit for bit with both leapfrogs
// (their last RHS, the DKD XSPH correction and the cached CFL step are checkpointed), and within the integration
// tolerance with ARKODE (which restarts from (t, y) with the saved step as its first step).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "run_helpers.hpp"
#include "sphmol/io/double_codec.hpp"

using namespace run_helpers;

namespace {
nlohmann::json checkpoint_at(const fs::path& dir, const std::string& t) {
  return json_file(dir / ("checkpoint-" + t) / "checkpoint.json");
}
}  // namespace

TEST_CASE("restart: interrupted + restarted run = uninterrupted run", "[restart][integration]") {
  for (const std::string integrator : {"leapfrog", "leapfrog_kdk", "arkode_erk"}) {
    DYNAMIC_SECTION(integrator) {
      const fs::path dir = scratch("restart-" + integrator);
      const std::string common = couette("--set output.times=[0.05] --set output.checkpoint_every=0.025 --set time.integrator=" + integrator);
      REQUIRE(sph_mol(common + " --output '" + (dir / "whole").string() + "' --set time.t_end=0.1", dir / "e1").code == 0);
      REQUIRE(sph_mol(common + " --output '" + (dir / "first").string() + "' --set time.t_end=0.05", dir / "e2").code == 0);
      const auto r = sph_mol("-q --restart '" + (dir / "first" / "checkpoint-0.05").string() + "' --output '" +
                                 (dir / "second").string() + "' --set time.t_end=0.1",
                             dir / "e3");
      INFO(r.err);
      REQUIRE(r.code == 0);

      // Only the two newest checkpoints are kept.
      CHECK(fs::exists(dir / "whole" / "checkpoint-0.1"));
      CHECK(fs::exists(dir / "whole" / "checkpoint-0.075"));
      CHECK_FALSE(fs::exists(dir / "whole" / "checkpoint-0.05"));

      const auto a = checkpoint_at(dir / "whole", "0.1"), b = checkpoint_at(dir / "second", "0.1");
      const auto summary = json_file(dir / "second" / "summary.json");
      CHECK(summary["status"] == "completed");
      CHECK(summary["restarted_from"]["t"] == 0.05);
      // The measurements before the restart are carried over, and so is the split of the wall time.
      CHECK(summary["errors"].size() == 2);
      const auto first = checkpoint_at(dir / "first", "0.05");
      CHECK(first["rhs_seconds"].get<double>() > 0.0);
      CHECK(summary["wall_seconds_breakdown"]["rhs_without_search"].get<double>() + summary["wall_seconds_breakdown"]["neighbour_search"].get<double>() >
            first["rhs_seconds"].get<double>());
      if (integrator != "arkode_erk") {
        CHECK(a["state"] == b["state"]);
        CHECK(a["integrator_state"] == b["integrator_state"]);
        CHECK(summary["steps"] == json_file(dir / "whole" / "summary.json")["steps"]);
      } else {
        // Within the tolerance: |dy| <= 10 (rtol |y|max + atol) per block (positions, velocities).
        const auto ya = sphmol::decode_doubles(a["state"]), yb = sphmol::decode_doubles(b["state"]);
        REQUIRE(ya.size() == yb.size());
        const std::size_t half = ya.size() / 2;
        for (std::size_t begin : {std::size_t{0}, half}) {
          double dmax = 0.0, ymax = 0.0;
          for (std::size_t k = begin; k < begin + half; ++k) {
            dmax = std::max(dmax, std::abs(ya[k] - yb[k]));
            ymax = std::max(ymax, std::abs(ya[k]));
          }
          INFO("block " << begin << ": max |dy| = " << dmax << ", max |y| = " << ymax);
          CHECK(dmax <= 10.0 * (1e-6 * ymax + 1e-12));
        }
      }
    }
  }
}

TEST_CASE("restart: bad checkpoint paths are input errors (exit 2, nothing written)", "[restart][integration]") {
  const fs::path dir = scratch("restart-bad");
  auto r = sph_mol("--restart '" + (dir / "nope").string() + "' --output '" + (dir / "out").string() + "'", dir / "e");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains("config.yaml not found"));
  fs::create_directories(dir / "fake");
  std::ofstream(dir / "fake" / "config.yaml") << slurp(std::string(SPHMOL_SOURCE_DIR) + "/verification/couette.yaml");
  std::ofstream(dir / "fake" / "checkpoint.json") << "{\"format\": \"something else\"}";
  r = sph_mol("--restart '" + (dir / "fake").string() + "' --output '" + (dir / "out").string() + "'", dir / "e");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains("unknown format"));
  // A checkpoint of the previous format (without the RHS and search seconds) names both formats.
  std::ofstream(dir / "fake" / "checkpoint.json") << "{\"format\": \"sph-mol checkpoint 1\"}";
  r = sph_mol("--restart '" + (dir / "fake").string() + "' --output '" + (dir / "out").string() + "'", dir / "e");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Matchers::Contains("'sph-mol checkpoint 1' (this build reads 'sph-mol checkpoint 2')"));
  CHECK_FALSE(fs::exists(dir / "out"));
}
