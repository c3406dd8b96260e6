// Probes in a built-in case: a point probe in verification/hydrostatic.yaml's tank reads the
// hydrostatic pressure, from t = 0 on; a gauge with its own `every` samples at its own times;
// output.every sets the output times; the files are listed in summary.json; probes the scene
// cannot hold are config errors (exit 2, FILE:LINE, no output folder).
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "integration/run_helpers.hpp"
#include "support/process.hpp"

using namespace run_helpers;

namespace {

std::vector<std::vector<std::string>> read_csv(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> r;
    std::stringstream s(line);
    for (std::string c; std::getline(s, c, ',');) r.push_back(c);
    if (!line.empty() && line.back() == ',') r.emplace_back();
    rows.push_back(r);
  }
  return rows;
}

// hydrostatic.yaml at 20 particles across (dx = 0.05 m, surface at 0.9 m), 2 s: settled after the
// 1 s gravity ramp.
fs::path write_config(const fs::path& dir, const std::string& probes) {
  std::string text = slurp(fs::path(SPHMOL_SOURCE_DIR) / "verification/hydrostatic.yaml");
  const auto out = text.find("output:");
  REQUIRE(out != std::string::npos);
  text = text.substr(0, out) + "output:\n  every: 1.0\n  plots: false\n" + probes;
  const fs::path cfg = dir / "probes.yaml";
  std::ofstream(cfg) << text;
  return cfg;
}

test_support::ProcessResult run(const fs::path& dir, const fs::path& cfg, const std::string& out) {
  return test_support::run_process(SPHMOL_BINARY,
                                   {"--config", cfg.string(), "--output", (dir / out).string(), "-q", "--set",
                                    "discretization.particles_across=20", "--set", "time.t_end=2.0"},
                                   (dir / (out + ".log")).string());
}

}  // namespace

TEST_CASE("probes: a point probe in the hydrostatic tank reads rho g depth", "[probes][integration]") {
  const fs::path dir = scratch("probes-hydrostatic");
  const fs::path cfg = write_config(dir, R"(probes:
  - {name: p_mid, type: point, at: [0.5, 0.45]}
  - {name: gauge, type: height_gauge, at: [0.5], every: 0.5}
  - {name: column, type: line, from: [0.5, 0.1], to: [0.5, 0.8], points: 8, fields: [p]}
)");
  const auto r = run(dir, cfg, "out");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const fs::path out = dir / "out";

  const auto p = read_csv(out / "probe_p_mid.csv");
  REQUIRE(p.size() == 4);  // header, t = 0 and the output times 1 and 2 (output.every: 1)
  CHECK(p[0] == std::vector<std::string>{"t [s]", "p [Pa]", "rho [kg/m^3]", "u [m/s]", "v [m/s]"});
  CHECK(std::stod(p[1][0]) == 0.0);
  CHECK(std::stod(p[2][0]) == 1.0);
  CHECK(std::stod(p[3][0]) == 2.0);
  // Settled: p = rho0 g (0.9 - 0.45) within the case's own accuracy (p_rms ~ 1 % of rho0 g H).
  const double exact = 1000.0 * 9.81 * 0.45;
  CHECK(std::stod(p[3][1]) == Approx(exact).epsilon(0.03));
  CHECK(std::abs(std::stod(p[3][4])) < 0.01);

  const auto g = read_csv(out / "probe_gauge.csv");
  REQUIRE(g.size() == 6);  // t = 0, 0.5, 1, 1.5, 2
  CHECK(g[0] == std::vector<std::string>{"t [s]", "y_surface [m]"});
  CHECK(std::stod(g[2][0]) == 0.5);
  CHECK(std::stod(g[5][1]) == Approx(0.9).margin(0.05));

  const auto line = read_csv(out / "probe_column.csv");
  REQUIRE(line.size() == 1 + 3 * 8);
  CHECK(line[0] == std::vector<std::string>{"t [s]", "x [m]", "y [m]", "p [Pa]"});
  for (const auto& row : line) CHECK(row.size() == 4);

  const auto summary = json_file(out / "summary.json");
  CHECK(summary["csv_files"].contains("probe_p_mid.csv"));
  CHECK(summary["csv_files"].contains("probe_gauge.csv"));
  const auto& files = summary["files"];
  CHECK(std::find(files.begin(), files.end(), "probe_column.csv") != files.end());
  // output.every: the case measured at t = 1 and 2 (not at t = 0).
  REQUIRE(summary["errors"].size() == 2);
  CHECK(summary["errors"][0]["t"].get<double>() == 1.0);
  // The resolved config keeps output.every and the probes.
  const std::string resolved = slurp(out / "config.yaml");
  CHECK(resolved.find("  every: 1\n") != std::string::npos);
  CHECK(resolved.find("  - name: gauge\n    type: height_gauge\n    every: 0.5\n") != std::string::npos);
}

TEST_CASE("probes: probes the scene cannot hold are config errors", "[probes][integration]") {
  const fs::path dir = scratch("probes-errors");
  {
    const fs::path cfg = write_config(dir, "probes:\n  - {name: f, type: force, body: floor}\n");
    const auto r = run(dir, cfg, "force");
    CHECK(r.code == 2);
    CHECK(r.err.find("config error: " + cfg.string() + ":") != std::string::npos);
    CHECK(r.err.find("probes[0].body: the scene has no wall body named 'floor'") != std::string::npos);
    CHECK(!fs::exists(dir / "force"));
  }
  {
    const fs::path cfg = write_config(dir, "probes:\n  - {name: far, type: point, at: [5.0, 0.5]}\n");
    const auto r = run(dir, cfg, "far");
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find("config error: " + cfg.string() + ":") != std::string::npos);
    CHECK(r.err.find("probes[0].at: the point (5, 0.5) is outside the scene") != std::string::npos);
    CHECK(!fs::exists(dir / "far"));
  }
}

TEST_CASE("probes: a restart from a checkpoint continues each series", "[probes][integration][restart]") {
  const fs::path dir = scratch("probes-restart");
  const fs::path cfg = write_config(dir, R"(probes:
  - {name: p_mid, type: point, at: [0.5, 0.45]}
  - {name: gauge, type: height_gauge, at: [0.5], every: 0.5}
)");
  const auto whole = test_support::run_process(
      SPHMOL_BINARY,
      {"--config", cfg.string(), "--output", (dir / "whole").string(), "-q", "--set", "discretization.particles_across=20",
       "--set", "time.t_end=2.0", "--set", "output.checkpoint_every=1.0"},
      (dir / "whole.log").string());
  INFO(whole.err);
  REQUIRE(whole.code == 0);
  // Into another folder: the rows before the checkpoint come from the checkpoint itself.
  const auto again = test_support::run_process(
      SPHMOL_BINARY, {"--restart", (dir / "whole" / "checkpoint-1").string(), "--output", (dir / "again").string(), "-q"},
      (dir / "again.log").string());
  INFO(again.err);
  REQUIRE(again.code == 0);
  for (const char* f : {"probe_p_mid.csv", "probe_gauge.csv"}) {
    INFO(f);
    CHECK(slurp(dir / "again" / f) == slurp(dir / "whole" / f));
  }
  CHECK(read_csv(dir / "again" / "probe_gauge.csv").size() == 6);
}

TEST_CASE("probes: a run that blows up writes the rows sampled before it", "[probes][integration][health]") {
  // The probes write at output times and at most once a second between them: a run that blew up
  // between output times left no probe file at all (or, after SIGINT, one that stopped at its last
  // write), while summary.json listed them. The tank at a step far above its stable one blows up
  // at t = 0.016 s, after the samples at t = 0 and 0.01 s.
  const fs::path dir = scratch("probes-blow-up");
  const auto r = test_support::run_process(
      SPHMOL_BINARY,
      {"--config", std::string(SPHMOL_SOURCE_DIR) + "/examples/tank_obstacle_2d.yaml", "--output", (dir / "run").string(), "-q",
       "--threads", "1", "--set", "discretization.spacing=0.02", "--set", "time.dt=4e-3", "--set", "time.t_end=0.5"},
      (dir / "run.log").string());
  INFO(r.err);
  REQUIRE(r.code == 3);
  const auto summary = json_file(dir / "run" / "summary.json");
  const double t_blow = summary["blow_up"]["t"].get<double>();
  CHECK(summary["csv_files"].contains("last_good_state.csv"));  // described like every other CSV
  for (const char* f : {"probe_bottom.csv", "probe_surface.csv", "probe_block.csv"}) {
    INFO(f);
    REQUIRE(fs::exists(dir / "run" / f));
    const auto rows = read_csv(dir / "run" / f);
    REQUIRE(rows.size() >= 3);  // the header and the samples at t = 0 and 0.01 s
    CHECK(std::stod(rows.back().at(0)) < t_blow);
    CHECK(std::find(summary["files"].begin(), summary["files"].end(), f) != summary["files"].end());
  }
}
