// The user scenes in examples/: every file loads as a valid configuration; the 2D tank runs through
// the binary, writes its probe CSVs with the documented headers and reads hydrostatics (pressure,
// surface height, buoyancy of the block); the 3D scenes run a few steps (their spacing is the
// coarsest their walls allow, so they run at it for a few milliseconds of simulated time).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "support/process.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path examples = fs::path(SPHMOL_SOURCE_DIR) / "examples";

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

struct Run {
  int code;
  std::string err;
  fs::path out;
  nlohmann::json summary;
};

// Runs `sph-mol --config examples/<file> --set ...` into a scratch folder (argv, no shell).
Run run_example(const std::string& file, const std::vector<std::string>& sets) {
  const fs::path dir = fs::temp_directory_path() / ("sphmol-examples-" + std::to_string(::getpid()) + "-" + file);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::vector<std::string> args{"--config", (examples / file).string(), "--output", (dir / "out").string(), "-q"};
  for (const auto& s : sets) {
    args.push_back("--set");
    args.push_back(s);
  }
  const auto r = test_support::run_process(SPHMOL_BINARY, args, (dir / "err.log").string());
  nlohmann::json s;
  if (std::ifstream f(dir / "out" / "summary.json"); f.good()) s = nlohmann::json::parse(f);
  return {r.code, r.err, dir / "out", s};
}

}  // namespace

TEST_CASE("examples: every examples/*.yaml is a valid configuration", "[integration][examples]") {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(examples))
    if (e.path().extension() == ".yaml") files.push_back(e.path());
  REQUIRE(files.size() >= 3);
  for (const auto& f : files) {
    INFO(f.string());
    CHECK_NOTHROW(sphmol::load_config(f.string(), {}));
  }
}

TEST_CASE("examples: the 2D tank runs and its probes read hydrostatics", "[integration][examples]") {
  const auto r = run_example("tank_obstacle_2d.yaml", {"time.t_end=0.1", "output.times=[0.1]"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.summary["status"] == "completed");
  CHECK(r.summary["scene"]["wall_bodies"] == nlohmann::json::array({"block"}));

  const auto bottom = read_csv(r.out / "probe_bottom.csv");
  const auto surface = read_csv(r.out / "probe_surface.csv");
  const auto block = read_csv(r.out / "probe_block.csv");
  REQUIRE(bottom.size() == 12);  // header, t = 0, 0.01, ..., 0.1 (every: 0.01)
  REQUIRE(surface.size() == 12);
  REQUIRE(block.size() == 12);
  CHECK(bottom[0] == std::vector<std::string>{"t [s]", "p [Pa]"});
  CHECK(surface[0] == std::vector<std::string>{"t [s]", "y_surface [m]"});
  CHECK(block[0] == std::vector<std::string>{"t [s]", "Fx [N/m]", "Fy [N/m]"});

  // The values the example's header promises, at every sample: p = rho0 g (0.3 - 0.05) at the
  // bottom probe, the surface at 0.3 m, the buoyancy rho0 g A = 49.05 N/m on the block, with the
  // acoustic oscillations of the start. Measured over the full run to t = 1 s: pressure within
  // 2.9 %, surface within 0.07 mm, Fy within 5.5 % (49.07 N/m at the end), |Fx| < 0.12 N/m.
  const double g = 9.81, rho0 = 1000.0;
  for (std::size_t i = 1; i < bottom.size(); ++i) {
    INFO("row " << i);
    CHECK(std::stod(bottom[i][1]) == Approx(rho0 * g * 0.25).epsilon(0.05));
    CHECK(std::stod(surface[i][1]) == Approx(0.3).margin(0.002));
    CHECK(std::stod(block[i][1]) == Approx(0.0).margin(0.5));
    CHECK(std::stod(block[i][2]) == Approx(rho0 * g * 0.1 * 0.05).epsilon(0.08));
  }
}

TEST_CASE("examples: the 3D scenes run a few steps and write their probes", "[integration][examples]") {
  struct Case {
    std::string file;
    std::string t_end;  // a few dozen steps, and no less than the probes' `every`
    std::vector<std::pair<std::string, std::vector<std::string>>> probes;  // name, CSV header
  };
  const std::vector<std::string> p{"t [s]", "p [Pa]"}, z{"t [s]", "z_surface [m]"},
      f{"t [s]", "Fx [N]", "Fy [N]", "Fz [N]"};
  const std::vector<Case> cases{
      {"dam_break_3d.yaml", "0.005", {{"p1", p}, {"p2", p}, {"p3", p}, {"p4", p}, {"h1", z}, {"h2", z}, {"h3", z}}},
      {"piston_3d.yaml", "0.01", {{"far_wall", p}, {"h_mid", z}, {"h_far", z}, {"plate", f}}},
      {"sloshing_3d.yaml", "0.02", {{"h_left", z}, {"h_right", z}, {"p_left", p}, {"tank", f}}},
  };
  for (const auto& c : cases) {
    INFO(c.file);
    const auto r = run_example(c.file, {"time.t_end=" + c.t_end, "output.times=[" + c.t_end + "]", "output.vtk=false"});
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK(r.summary["status"] == "completed");
    CHECK(r.summary["steps"].get<int>() > 5);
    for (const auto& [name, header] : c.probes) {
      const auto rows = read_csv(r.out / ("probe_" + name + ".csv"));
      INFO(name);
      REQUIRE(rows.size() >= 2);  // header, t = 0, then the samples up to t_end
      CHECK(rows[0] == header);
      CHECK(std::stod(rows.back()[0]) == Approx(std::stod(c.t_end)));
    }
  }
}
