// The probe observer on a tank at hydrostatic rest: a point probe reads p = rho0 g (H - y), a point
// above the water gives empty cells, a line writes one row per point with its coordinates, the
// height gauge finds the surface, the force probe the floor's load; a point outside the scene is a
// config error at the probe's line; the rows survive save_state / restore_state.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "probe_tank.hpp"
#include "sphmol/probes/probe_observer.hpp"
#include "sphmol/rhs/assemble.hpp"

using namespace sphmol;
using namespace probe_tank;
namespace fs = std::filesystem;

namespace {

ProbeConfig probe(const std::string& name, const std::string& type) {
  ProbeConfig p;
  p.name = name;
  p.type = type;
  p.where = "case.yaml:7: probes[0].at";
  if (type != "force" && type != "height_gauge") p.fields = {"p", "rho", "velocity"};
  return p;
}

std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string c; std::getline(s, c, ',');) out.push_back(c);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("sphmol-probes-" + std::to_string(::getpid()) + "-" +
                                        std::to_string(reinterpret_cast<std::uintptr_t>(this)));
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

struct Fixture {
  Config c = tank_config();
  std::unique_ptr<SphSystem<2>> sys;
  std::vector<double> y, scratch;
  Fixture() {
    Domain<2> dom;
    dom.lo = {-1, -1};
    dom.hi = {2, 2};
    c.time.t_end = 1.0;
    c.output.times = {1.0};
    auto pt = probe("p_mid", "point");
    pt.at = {0.5 * kW, 0.5 * kH};
    auto above = probe("above", "point");
    above.at = {0.5 * kW, kH + 4 * kDx};  // 4.5 dx above the top row: beyond the support 4 dx
    auto line = probe("depth_line", "line");
    line.from = {0.5 * kW, 0.2};  // the kernel (support 0.2 m) stays inside the water
    line.to = {0.5 * kW, 0.4};
    line.points = {4};
    line.fields = {"p"};
    auto gauge = probe("gauge", "height_gauge");
    gauge.at = {0.3};
    auto floor = probe("floor", "force");
    floor.body = "floor";
    floor.body_index = 0;
    auto corner_l = probe("corner_l", "force"), corner_r = probe("corner_r", "force");
    corner_l.body_index = 3;
    corner_r.body_index = 4;
    c.probes = {pt, above, line, gauge, floor, corner_l, corner_r};
    sys = assemble_system<2>(c, tank(), dom, kDx);
    y = sys->initial_state();
    sys->refresh_fields(0.0, y.data(), scratch);
  }
};

}  // namespace

TEST_CASE("probe observer: CSV files of points, lines, gauges and forces", "[probes][observer]") {
  Fixture f;
  TempDir dir;
  OutputSink out{dir.path.string(), true};
  ProbeObserver<2> obs(f.c, *f.sys);
  obs.at_output(*f.sys, f.y.data(), 0.0, out);

  const auto pt = lines_of(dir.path / "probe_p_mid.csv");
  REQUIRE(pt.size() == 2);
  CHECK(pt[0] == "t [s],p [Pa],rho [kg/m^3],u [m/s],v [m/s]");
  const auto row = cells(pt[1]);
  REQUIRE(row.size() == 5);
  CHECK(std::stod(row[0]) == 0.0);
  // The fluid's pressure is linear in depth, which the Shepard interpolant reproduces in the bulk.
  CHECK(std::stod(row[1]) == Approx(kRho0 * kG * 0.5 * kH).epsilon(1e-3));
  CHECK(std::stod(row[3]) == 0.0);

  const auto above = lines_of(dir.path / "probe_above.csv");
  REQUIRE(above.size() == 2);
  CHECK(above[1] == "0,,,,");  // no fluid within the kernel support: empty cells

  const auto line = lines_of(dir.path / "probe_depth_line.csv");
  REQUIRE(line.size() == 5);
  CHECK(line[0] == "t [s],x [m],y [m],p [Pa]");
  for (int k = 0; k < 4; ++k) {
    const auto r = cells(line[1 + k]);
    const double yk = 0.2 + 0.2 / 3 * k;
    CHECK(std::stod(r[2]) == Approx(yk));
    CHECK(std::stod(r[3]) == Approx(kRho0 * kG * (kH - yk)).epsilon(2e-3));
  }

  const auto gauge = lines_of(dir.path / "probe_gauge.csv");
  REQUIRE(gauge.size() == 2);
  CHECK(gauge[0] == "t [s],y_surface [m]");
  CHECK(std::stod(cells(gauge[1])[1]) == Approx(kH).margin(0.5 * kDx));

  const auto force = lines_of(dir.path / "probe_floor.csv");
  REQUIRE(force.size() == 2);
  CHECK(force[0] == "t [s],Fx [N/m],Fy [N/m]");
  // The floor and the two corners below the side walls carry the water's weight.
  const auto fy = [&](const std::string& name) { return std::stod(cells(lines_of(dir.path / name)[1])[2]); };
  CHECK(fy("probe_floor.csv") + fy("probe_corner_l.csv") + fy("probe_corner_r.csv") ==
        Approx(-kRho0 * kG * kH * kW).epsilon(0.005));

  // Every file is in the run's ledger, and described for the summary.
  CHECK(out.written().size() == 7);
  nlohmann::json summary;
  obs.annotate(summary);
  CHECK(summary["csv_files"].contains("probe_floor.csv"));

  // A second sample appends a row; a fresh observer restored from the state continues the series.
  obs.at_output(*f.sys, f.y.data(), 0.5, out);
  CHECK(lines_of(dir.path / "probe_p_mid.csv").size() == 3);
  const auto state = obs.save_state();
  ProbeObserver<2> again(f.c, *f.sys);
  again.restore_state(state, out);
  again.at_output(*f.sys, f.y.data(), 1.0, out);
  const auto cont = lines_of(dir.path / "probe_p_mid.csv");
  REQUIRE(cont.size() == 4);
  CHECK(cells(cont[2])[0] == "0.5");
  CHECK(cells(cont[3])[0] == "1");
  // Every probe but `above`, which no fluid reaches: all its cells are empty, and gnuplot failed on
  // a plot with no points ("x range is invalid"), a warning per such probe.
  const auto plots = again.plots(out);
  CHECK(plots.size() == 6);
  for (const auto& p : plots) CHECK(p.png != "probe_above.png");
}

TEST_CASE("probe observer: `every` probes ask the run loop for their own times", "[probes][observer]") {
  Fixture f;
  f.c.probes.resize(1);
  f.c.probes[0].every = 0.3;
  TempDir dir;
  OutputSink out{dir.path.string(), true};
  ProbeObserver<2> obs(f.c, *f.sys);
  CHECK(obs.next_time() == 0.0);
  obs.at_output(*f.sys, f.y.data(), 0.0, out);  // output times do not sample an `every` probe
  CHECK(obs.next_time() == 0.0);
  std::vector<double> sampled;
  for (double t = obs.next_time(); t <= 1.0; t = obs.next_time()) {
    obs.at_time(*f.sys, f.y.data(), t, out);
    sampled.push_back(t);
  }
  obs.at_stop(out);
  // 0, 0.3, 0.6, 0.9 and the end state at t_end = 1, which is not a multiple of every.
  REQUIRE(sampled.size() == 5);
  CHECK(sampled[3] == Approx(0.9));
  CHECK(sampled[4] == 1.0);
  CHECK(lines_of(dir.path / "probe_p_mid.csv").size() == 6);
}

TEST_CASE("probe observer: a probe outside the scene is a config error at its line", "[probes][observer]") {
  Fixture f;
  f.c.probes.resize(1);
  f.c.probes[0].at = {0.5, 3.0};
  try {
    ProbeObserver<2> obs(f.c, *f.sys);
    FAIL("no error");
  } catch (const ConfigError& e) {
    const std::string m = e.what();
    CHECK(m.rfind("case.yaml:7: probes[0].at: the point (0.5, 3) is outside the scene", 0) == 0);
  }
  // A gauge whose range lies above the scene.
  f.c.probes[0].type = "height_gauge";
  f.c.probes[0].at = {0.5};
  f.c.probes[0].range = {5.0, 6.0};
  try {
    ProbeObserver<2> obs(f.c, *f.sys);
    FAIL("no error");
  } catch (const ConfigError& e) {
    CHECK_THAT(e.what(), Catch::StartsWith("case.yaml:7: probes[0].at: the gauge's range [5, 6] lies outside the scene"));
  }
  f.c.probes[0].range.clear();
  f.c.probes[0].at = {0.5, 0.3};
  f.c.probes[0].type = "force";
  f.c.probes[0].body = "lid";
  f.c.probes[0].body_index = 5;  // no wall particle carries it
  CHECK_THROWS_AS(ProbeObserver<2>(f.c, *f.sys), ConfigError);
}

TEST_CASE("probe observer: a plane in 3D writes every grid point with its coordinates", "[probes][observer]") {
  // A block of 8^3 fluid particles, no walls, at hydrostatic density in z.
  Config c = tank_config();
  c.dimension = 3;
  c.fluid.body_force = {0.0, 0.0, -kG};
  c.time.t_end = 1.0;
  c.output.times = {1.0};
  const int n = 8;
  const double top = n * kDx;
  Particles<3> P;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double z = (k + 0.5) * kDx;
        const double rho = kRho0 + kRho0 * kG * (top - z) / (kC * kC);
        P.add(Kind::Fluid, {(i + 0.5) * kDx, (j + 0.5) * kDx, z}, {0, 0, 0}, rho * kDx * kDx * kDx, rho);
      }
  Domain<3> dom;
  dom.lo = {-1, -1, -1};
  dom.hi = {2, 2, 2};
  ProbeConfig plane = probe("mid", "plane");
  plane.origin = {0.075, 0.075, 0.1};
  plane.edge_1 = {0.05, 0, 0};
  plane.edge_2 = {0, 0.05, 0};
  plane.points = {3, 2};
  plane.fields = {"p"};
  c.probes = {plane};
  auto sys = assemble_system<3>(c, std::move(P), dom, kDx);
  std::vector<double> y = sys->initial_state(), scratch;
  sys->refresh_fields(0.0, y.data(), scratch);
  TempDir dir;
  OutputSink out{dir.path.string(), true};
  ProbeObserver<3> obs(c, *sys);
  obs.at_output(*sys, y.data(), 0.0, out);
  const auto rows = lines_of(dir.path / "probe_mid.csv");
  REQUIRE(rows.size() == 7);
  CHECK(rows[0] == "t [s],x [m],y [m],z [m],p [Pa]");
  const auto second = cells(rows[2]);  // edge_1 fastest: (0.1, 0.075, 0.1)
  CHECK(std::stod(second[1]) == Approx(0.1));
  CHECK(std::stod(second[2]) == Approx(0.075));
  // p is linear in z and the particles within the support (0.1 m) lie symmetrically about z = 0.1.
  for (int r = 1; r <= 6; ++r) CHECK(std::stod(cells(rows[r])[4]) == Approx(kRho0 * kG * (top - 0.1)).epsilon(1e-6));
}

TEST_CASE("probe observer: a height gauge beside a wall reads the surface", "[probes][observer]") {
  // On the left wall's face (x = 0), half a spacing and one spacing from it, and mid-tank: the fluid
  // fills only the part of the support the wall leaves open, so the plain kernel sum read empty on
  // the face and low beside it.
  Fixture f;
  f.c.probes.clear();
  std::vector<double> reads;
  for (const double x : {0.0, 0.5 * kDx, kDx, 2.0 * kDx, 0.5 * kW}) {
    auto g = probe("g" + std::to_string(f.c.probes.size()), "height_gauge");
    g.at = {x};
    f.c.probes.push_back(g);
  }
  TempDir dir;
  OutputSink out{dir.path.string(), true};
  ProbeObserver<2> obs(f.c, *f.sys);
  obs.on_sample = [&](const std::string&, double, const std::vector<double>& v) { reads.push_back(v.at(0)); };
  obs.at_output(*f.sys, f.y.data(), 0.0, out);
  REQUIRE(reads.size() == 5u);
  for (const double r : reads) {
    INFO(r);
    CHECK(r == Approx(kH).margin(0.5 * kDx));
  }
  // The wall's face and mid-tank read alike, to a fraction of a spacing.
  CHECK(reads[0] == Approx(reads[4]).margin(0.25 * kDx));
}
