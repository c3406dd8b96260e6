// Ghost mirror planes of user scenes through the sph-mol binary: a tank whose floor and sides are
// plane bodies along the axes behaves as the same tank with the domain's faces as mirrors, and the
// same tank tilted by 30 degrees (its gravity with it) settles to rest with the hydrostatic pressure.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "run_helpers.hpp"

using namespace run_helpers;

namespace {

// The YAML of a 0.3 x 0.2 m water column with mirror walls: `walls` holds the wall-body list (or
// nothing, then the domain's faces are the mirrors), `domain` the domain, `g` the body force.
std::string column(const std::string& domain, const std::string& fluid, const std::string& walls, const std::string& g,
                   const std::string& probe, double t_end) {
  std::ostringstream y;
  y << "case: scene\ndimension: 2\nfluid:\n  density: 1000.0\n  kinematic_viscosity: 1.0e-3\n"
       "  eos: {type: tait, sound_speed: 20.0, gamma: 7.0}\n  body_force: "
    << g << "\nscene:\n  domain: " << domain << "\n  fluid:\n    - shape: " << fluid << "\n      pressure: hydrostatic\n"
    << walls
    << "discretization:\n  spacing: 0.01\n  boundary: ghost\n  density: continuity\n  artificial_viscosity: {alpha: 0.1}\n"
       "time:\n  t_end: "
    << t_end << "\n  integrator: leapfrog\noutput:\n  times: [" << t_end
    << "]\n  plots: false\n  profiles: false\nprobes:\n  - name: deep\n    type: point\n    at: " << probe << "\n";
  return y.str();
}

struct Outcome {
  nlohmann::json summary;
  double p_deep;  // the probe's last pressure [Pa]
};

Outcome run(const std::string& name, const std::string& yaml) {
  const fs::path dir = scratch("ghost-planes-" + name);
  std::ofstream(dir / "scene.yaml") << yaml;
  const auto r = sph_mol("-q --threads 1 --config '" + (dir / "scene.yaml").string() + "' --output '" + (dir / "out").string() + "'",
                         dir / "err.log");
  INFO(name << ": " << r.err);
  REQUIRE(r.code == 0);
  Outcome o{json_file(dir / "out" / "summary.json"), 0.0};
  std::ifstream csv(dir / "out" / "probe_deep.csv");
  std::string line, last;
  while (std::getline(csv, line))
    if (!line.empty()) last = line;
  o.p_deep = std::stod(last.substr(last.find(',') + 1));
  fs::remove_all(dir);
  return o;
}

}  // namespace

TEST_CASE("ghost planes: plane bodies along the axes are the domain's mirror faces", "[integration][scene][ghost]") {
  const std::string fluid = "{type: box, lo: [0, 0.05], hi: [0.3, 0.25]}", g = "[0.0, -9.81]", probe = "[0.15, 0.1]";
  const auto faces = run("faces", column("{lo: [0, 0.05], hi: [0.3, 0.4], open_faces: [y_hi]}", fluid, "", g, probe, 0.3));
  const auto planes = run("planes", column("{lo: [0, 0], hi: [0.3, 0.4], boundaries: [open, open]}", fluid,
                                           "  walls:\n    - shape: {type: plane, point: [0, 0.05], normal: [0, 1]}\n"
                                           "    - shape: {type: plane, point: [0, 0], normal: [1, 0]}\n"
                                           "    - shape: {type: plane, point: [0.3, 0], normal: [-1, 0]}\n",
                                           g, probe, 0.3));
  CHECK(planes.summary["scene"]["wall_treatments"] == nlohmann::json::array({"ghost", "ghost", "ghost"}));
  // The same particles and images (the lattice origin and the images' order differ: round-off only).
  const auto& a = faces.summary["final_errors"];
  const auto& b = planes.summary["final_errors"];
  CHECK(b["fluid_mass"].get<double>() == Approx(a["fluid_mass"].get<double>()).epsilon(1e-12));
  CHECK(b["max_speed"].get<double>() == Approx(a["max_speed"].get<double>()).epsilon(1e-6));
  CHECK(b["kinetic_energy"].get<double>() == Approx(a["kinetic_energy"].get<double>()).epsilon(1e-6));
  CHECK(planes.p_deep == Approx(faces.p_deep).epsilon(1e-9));
  // Both at rest: measured max speed 1.6e-5 of sqrt(2 g H) after 1 s.
  CHECK(a["max_speed_ratio"].get<double>() < 1e-4);
}

TEST_CASE("ghost planes: a tank tilted by 30 degrees with its gravity settles to rest, hydrostatic", "[integration][scene][ghost]") {
  // The tank's frame: along t = (cos 30, sin 30), up n = (-sin 30, cos 30); floor corner at (0.15, 0.02),
  // 0.3 m wide, 0.2 m of water; gravity -9.81 n. The mirrors are the floor and the two sides, at right
  // angles to it; the domain's faces are open. The lattice stays axis-aligned, so the first particles
  // lie between half a spacing and more from the tilted mirrors, and the column settles from that
  // start (measured at 3 s: max speed 0.0041 of sqrt(2 g H), kinetic energy 1.9e-6 of M g H, the
  // probe 2.4 % under rho g depth; the same tank with extrapolated wall particles still swings by
  // +-30 % at the probe then).
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6), W = 0.3, H = 0.2;
  const auto pt = [](double x, double y) {
    std::ostringstream o;
    o.precision(15);
    o << "[" << x << ", " << y << "]";
    return o.str();
  };
  const double x0 = 0.15, y0 = 0.02;
  const std::string fluid = "{type: polygon, vertices: [" + pt(x0, y0) + ", " + pt(x0 + W * c, y0 + W * s) + ", " +
                            pt(x0 + W * c - H * s, y0 + W * s + H * c) + ", " + pt(x0 - H * s, y0 + H * c) + "]}";
  const std::string walls = "  walls:\n    - {name: floor, shape: {type: plane, point: " + pt(x0, y0) + ", normal: " + pt(-s, c) +
                            "}}\n    - {name: left, shape: {type: plane, point: " + pt(x0, y0) + ", normal: " + pt(c, s) +
                            "}}\n    - {name: right, shape: {type: plane, point: " + pt(x0 + W * c, y0 + W * s) +
                            ", normal: " + pt(-c, -s) + "}}\n";
  const double depth = 0.15;  // the probe: mid-width, 0.05 m above the floor
  const std::string probe = pt(x0 + 0.5 * W * c - 0.05 * s, y0 + 0.5 * W * s + 0.05 * c);
  const auto r = run("tilted", column("{lo: [0, 0], hi: [0.45, 0.4], boundaries: [open, open]}", fluid, walls,
                                      pt(9.81 * s, -9.81 * c), probe, 3.0));
  const auto& e = r.summary["final_errors"];
  CHECK(e["max_speed_ratio"].get<double>() < 0.01);
  CHECK(e["kinetic_energy_change"].get<double>() < 1e-5);
  CHECK(r.p_deep == Approx(1000.0 * 9.81 * depth).epsilon(0.04));
}
