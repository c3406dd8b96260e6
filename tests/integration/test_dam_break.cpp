// Dam break at a CI-cheap resolution: dp = 0.04 (25 x 50 fluid + 252 wall particles), until
// t = 0.5 s, before the surge reaches the right wall (t ~ 0.7 s at this resolution). About 4 s CPU.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <utility>

#include "sphmol/config/config.hpp"
#include "sphmol/run/run_case.hpp"
#include "sphmol/studies/study_run.hpp"

using namespace sphmol;

TEST_CASE("dam_break: mass exact, no wall penetration, front between Martin & Moyce and Ritter (dp = 0.04)",
          "[integration][dam_break]") {
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml",
                               {"discretization.spacing=0.04", "time.t_end=0.5",
                                "output.times=[0.1, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5]", "output.plots=false"});
  RunOptions opt;
  opt.write_files = false;
  const auto s = run_case(c, opt);
  REQUIRE(s["status"] == "completed");
  const auto& f = s["final_errors"];
  INFO(f.dump());
  CHECK(f["mass_change"].get<double>() == 0.0);
  CHECK(f["wall_penetrations"].get<long>() == 0);
  CHECK(f["free_surge_outputs"].get<int>() == 8);
  // Upper bound: Ritter's shallow-water front a + 2 sqrt(gH) t (measured: at most 0.41 of its advance).
  CHECK(f["front_max_over_ritter"].get<double>() < 0.7);
  // Lower bound: the experiments (Martin & Moyce 1952, n^2 = 2), which SPH without wall friction and
  // without the experiments' gate-opening delay leads (measured: +0.22 a on average at this resolution, and within 0.02 a of Koshizuka & Oka at t = 0.1 s);
  // a front stalled by the walls, or gravity too weak, falls behind them.
  CHECK(f["front_mean_martin_moyce"].get<double>() > 0.0);
  CHECK(f["front_rms_martin_moyce"].get<double>() < 0.4);
  // One fused pass: each thread's time on its pair rows is reported, and it is part of the RHS time.
  const auto& rows = s["wall_seconds_breakdown"]["pair_rows_per_thread"];
  REQUIRE(rows.size() >= 1);
  double row_seconds = 0.0;
  for (const auto& r : rows) row_seconds += r.get<double>();
  CHECK(rows[0].get<double>() > 0.0);
  CHECK(row_seconds <= static_cast<double>(rows.size()) * s["wall_seconds_breakdown"]["rhs_without_search"].get<double>());
  for (const auto& e : s["errors"]) {
    INFO("t = " << e["t"]);
    CHECK(e["x_front"].get<double>() < e["x_ritter"].get<double>());
    if (!e["x_ko"].is_null()) CHECK(e["x_front"].get<double>() > e["x_ko"].get<double>() - 0.1);
  }
}

// The experiments (Martin & Moyce 1952, n^2 = 2; Koshizuka & Oka 1996) are for a column H = 2a: another
// column keeps the Ritter comparison and reports theirs as not applicable, with a notice.
TEST_CASE("dam_break: a column with H != 2a is not compared with the H = 2a experiments (dp = 0.05)", "[integration][dam_break]") {
  auto run = [](const std::string& column) {
    const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml",
                                 {"discretization.spacing=0.05", "time.t_end=0.2", "output.times=[0.1, 0.2]",
                                  "output.plots=false", "geometry.column=" + column});
    bool notice = false;
    for (const auto& n : c.notices) notice = notice || n.find("geometry.column: H/a = ") != std::string::npos;
    RunOptions opt;
    opt.write_files = false;
    return std::make_pair(notice, run_case(c, opt));
  };
  SECTION("a square column: null, with a notice") {
    const auto [notice, s] = run("[1.0, 1.0]");
    CHECK(notice);
    CHECK(s["experiments_compared"] == false);
    const auto& f = s["final_errors"];
    INFO(f.dump());
    for (const char* k : {"front_rms_martin_moyce", "front_mean_martin_moyce", "front_rms_koshizuka_oka"}) CHECK(f[k].is_null());
    CHECK(f["front_max_over_ritter"].is_number());
    for (const auto& e : s["errors"]) {
      CHECK(e["x_mm"].is_null());
      CHECK(e["x_ko"].is_null());
    }
  }
  SECTION("the experiments' column H = 2a: compared, no notice") {
    const auto [notice, s] = run("[1.0, 2.0]");
    CHECK_FALSE(notice);
    CHECK(s["experiments_compared"] == true);
    const auto& f = s["final_errors"];
    INFO(f.dump());
    CHECK(f["front_rms_martin_moyce"].is_number());
    CHECK(f["front_rms_koshizuka_oka"].is_number());
  }
}

TEST_CASE("dam_break: the studies compare a column other than H = 2a through its front with a reference run",
          "[integration][dam_break][studies]") {
  // Without the experiments there is no exact reference: the studies' error is the final front
  // position x_front, compared with a finer run (it was the null Martin & Moyce error: no run measured).
  const auto config = [](const std::string& column) {
    return load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml",
                       {"discretization.spacing=0.1", "geometry.column=" + column, "time.t_end=0.1", "output.times=[]",
                        "output.plots=false"});
  };
  const Config square = config("[1.0, 1.0]");
  CHECK_FALSE(case_has_exact_reference(square));
  CHECK(case_has_exact_reference(config("[1.0, 2.0]")));
  const StudyRun r = run_study_case(square);
  CHECK(r.summary["primary_error"] == "x_front");
  CHECK(std::isfinite(r.error));
  CHECK(r.note.empty());
}
