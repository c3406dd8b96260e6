// Checkpoint/restart with the IMEX integrators: a Couette run stopped at t = 0.05 and continued with
// --restart to 0.1 agrees with the uninterrupted run bit for bit (leapfrog_imex, whose checkpoint holds
// f_I = L v + b of the operator recorded at the step's predicted state) or to rtol/atol (arkode_imex,
// which restarts from (t, y) with the saved step).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "run_helpers.hpp"
#include "sphmol/io/double_codec.hpp"

using namespace run_helpers;

TEST_CASE("restart: IMEX integrators continue a checkpointed run", "[restart][integration][imex]") {
  for (const std::string integrator : {"leapfrog_imex", "arkode_imex"}) {
    DYNAMIC_SECTION(integrator) {
      const fs::path dir = scratch("restart-" + integrator);
      const std::string common = couette("--set output.times=[0.05] --set output.checkpoint_every=0.025 --set time.integrator=" +
                                         integrator + (integrator == "arkode_imex" ? " --set time.table=ARKODE_ARK324L2SA_ERK_4_2_3" : ""));
      REQUIRE(sph_mol(common + " --output '" + (dir / "whole").string() + "' --set time.t_end=0.1", dir / "e1").code == 0);
      REQUIRE(sph_mol(common + " --output '" + (dir / "first").string() + "' --set time.t_end=0.05", dir / "e2").code == 0);
      const auto r = sph_mol("-q --restart '" + (dir / "first" / "checkpoint-0.05").string() + "' --output '" +
                                 (dir / "second").string() + "' --set time.t_end=0.1",
                             dir / "e3");
      INFO(r.err);
      REQUIRE(r.code == 0);
      const auto a = json_file(dir / "whole" / "checkpoint-0.1" / "checkpoint.json");
      const auto b = json_file(dir / "second" / "checkpoint-0.1" / "checkpoint.json");
      CHECK(json_file(dir / "second" / "summary.json")["status"] == "completed");
      const auto ya = sphmol::decode_doubles(a["state"]), yb = sphmol::decode_doubles(b["state"]);
      REQUIRE(ya.size() == yb.size());
      if (integrator == "leapfrog_imex") {
        std::size_t differ = 0;
        for (std::size_t k = 0; k < ya.size(); ++k) differ += std::memcmp(&ya[k], &yb[k], sizeof(double)) != 0;
        CHECK(differ == 0);
      }
      const std::size_t half = ya.size() / 2;
      for (std::size_t begin : {std::size_t{0}, half}) {
        double dmax = 0.0, ymax = 0.0;
        for (std::size_t k = begin; k < begin + half; ++k) {
          dmax = std::max(dmax, std::abs(ya[k] - yb[k]));
          ymax = std::max(ymax, std::abs(ya[k]));
        }
        INFO("block " << begin << ": max |dy| = " << dmax << ", max |y| = " << ymax);
        CHECK(dmax <= 1e-5 * ymax);
      }
    }
  }
}
