// The scene builder: particle counts and positions against the box cases and against direct lattice
// counts, wall bodies (circle, cylinder, mesh) with their body index, overlapping fluid bodies,
// hydrostatic initial pressure and velocity expressions, and every scene that makes no sense.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <tuple>
#include <unistd.h>

#include "scene_test_support.hpp"
#include "sphmol/geometry/box_shape.hpp"
#include "sphmol/geometry/half_space_shape.hpp"
#include "sphmol/geometry/lattice.hpp"
#include "sphmol/cases/scene/scene_settings.hpp"
#include "sphmol/scenes/box_scene.hpp"
#include "sphmol/scenes/lattice_mass.hpp"

using namespace sphmol;
using scene_test::config;
using scene_test::error_of;
using scene_test::read;

namespace {

template <int D>
std::size_t count_kind(const Particles<D>& p, Kind k) {
  std::size_t n = 0;
  for (auto x : p.kind) n += x == k;
  return n;
}

// The pressure above the rest state that the linear EOS gives for particle i's density.
double gauge_pressure(const Config& c, double rho) {
  return c.fluid.eos.sound_speed * c.fluid.eos.sound_speed * (rho - c.fluid.density);
}

}  // namespace

TEST_CASE("scene builder: a hydrostatic tank gives the box scene's particles exactly", "[scene]") {
  Config c = config(2, 0.05);
  BoxWalls<2> walls{};
  walls[0][0].present = walls[0][1].present = walls[1][0].present = true;
  const BoxScene box = build_box_scene(c, 1.0, 0.6, 0.5, walls, false);
  const auto s = build_scene<2>(read(R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 0.6], boundaries: [wall, wall], open_faces: [y_hi]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [1, 0.5]}
)yaml",
                                     2),
                                c);
  const auto& P = s.particles;
  const auto& Q = box.particles;
  REQUIRE(P.size() == Q.size());
  REQUIRE(P.n_fluid == Q.n_fluid);
  CHECK(P.n_fluid == 200u);
  CHECK(s.spacing == box.spacing);
  CHECK(s.wall_layers == box.wall_layers);
  // Same points in the same order, with the same masses, densities, normals and depths.
  for (std::size_t i = 0; i < P.size(); ++i) {
    INFO(i);
    CHECK(P.kind[i] == Q.kind[i]);
    for (int d = 0; d < 2; ++d) {
      CHECK(P.x[d][i] == Approx(Q.x[d][i]).margin(1e-12));
      CHECK(P.wall_normal[d][i] == Q.wall_normal[d][i]);
      CHECK(P.v[d][i] == Q.v[d][i]);
    }
    CHECK(P.mass[i] == Q.mass[i]);
    CHECK(P.rho[i] == Q.rho[i]);
    CHECK(P.wall_depth[i] == Approx(Q.wall_depth[i]).margin(1e-12));
    CHECK(P.body[i] == -1);
  }
  for (int d = 0; d < 2; ++d) {
    CHECK(s.domain.lo[d] == Approx(box.domain.lo[d]));
    CHECK(s.domain.hi[d] == Approx(box.domain.hi[d]));
    CHECK(s.domain.periodic[d] == box.domain.periodic[d]);
  }
  CHECK_FALSE(s.ghost);
  CHECK_FALSE(s.fills_domain);
  CHECK(s.open_faces);
  // The bound used before building holds, and is not far off for a tank mostly full.
  const double bound = scene_particle_bound(read(R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 0.6], boundaries: [wall, wall], open_faces: [y_hi]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [1, 0.5]}
)yaml", 2), c);
  CHECK(bound >= static_cast<double>(P.size()));
  CHECK(bound < 2.0 * static_cast<double>(P.size()));
}

TEST_CASE("scene builder: a circular obstacle removes exactly the fluid points within half a spacing of it", "[scene]") {
  const double dx = 0.02;
  Config c = config(2, dx);
  const auto s = build_scene<2>(read(R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 1]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [1, 0.8]}
  walls:
    - name: cylinder
      shape: {type: sphere, centre: [0.5, 0.4], radius: 0.15}
)yaml",
                                     2),
                                c);
  const auto& P = s.particles;
  // Lattice count of the fluid box minus its points inside the circle grown by dx/2.
  std::size_t expected = 0;
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 50; ++i) {
      const double x = (i + 0.5) * dx - 0.5, y = (j + 0.5) * dx - 0.4;
      expected += std::sqrt(x * x + y * y) - 0.15 >= 0.5 * dx - 1e-12;
    }
  CHECK(P.n_fluid == expected);
  CHECK(P.n_fluid < 2000u);
  REQUIRE(s.body_names == std::vector<std::string>{"cylinder"});
  std::size_t body = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double rx = P.x[0][i] - 0.5, ry = P.x[1][i] - 0.4, r = std::sqrt(rx * rx + ry * ry);
    if (P.kind[i] == Kind::Fluid) {
      CHECK(r - 0.15 >= 0.5 * dx - 1e-12);
      CHECK(P.body[i] == -1);
      continue;
    }
    if (P.body[i] != 0) continue;
    ++body;
    CHECK(r < 0.15);
    CHECK(P.wall_depth[i] == Approx(0.15 - r));
    CHECK(P.wall_depth[i] <= s.wall_layers * dx + 1e-12);
    if (r > 1e-9) CHECK((P.wall_normal[0][i] * rx + P.wall_normal[1][i] * ry) / r == Approx(1.0).epsilon(1e-6));
  }
  // The ring of wall layers, within the lattice's granularity.
  const double ri = 0.15 - s.wall_layers * dx;
  CHECK(body * dx * dx == Approx(M_PI * (0.15 * 0.15 - ri * ri)).epsilon(0.1));
  // Domain walls on all four faces, body -1.
  CHECK(count_kind(P, Kind::Wall) - body == 4u * s.wall_layers * (50u + s.wall_layers));
}

TEST_CASE("scene builder: a cylinder through a 3D box, cut at the domain faces", "[scene]") {
  const double dx = 0.05;
  Config c = config(3, dx);
  const auto s = build_scene<3>(read(R"yaml(scene:
  domain: {lo: [0, 0, 0], hi: [0.5, 0.5, 0.5]}
  fluid:
    - shape: {type: box, lo: [0, 0, 0], hi: [0.5, 0.5, 0.5]}
  walls:
    - shape: {type: cylinder, start: [0.25, 0.25, -0.2], end: [0.25, 0.25, 0.7], radius: 0.1}
      layers: 2
)yaml",
                                     3),
                                c);
  const auto& P = s.particles;
  std::size_t expected_fluid = 0, expected_body = 0;
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 10; ++i) {
        const double x = (i + 0.5) * dx - 0.25, y = (j + 0.5) * dx - 0.25, r = std::sqrt(x * x + y * y);
        expected_fluid += r - 0.1 >= 0.5 * dx - 1e-12;
        expected_body += r < 0.1 && 0.1 - r <= 2 * dx + 1e-12;
      }
  CHECK(P.n_fluid == expected_fluid);
  std::size_t body = 0;
  for (std::size_t i = P.n_fluid; i < P.size(); ++i)
    if (P.body[i] == 0) {
      ++body;
      CHECK(P.x[2][i] > 0.0);
      CHECK(P.x[2][i] < 0.5);
      CHECK(P.wall_normal[2][i] == Approx(0.0).margin(1e-6));  // the side, not the far-away caps
    }
  CHECK(body == expected_body);
  CHECK(s.fills_domain);  // around the cylinder
  CHECK_FALSE(s.open_faces);
}

TEST_CASE("scene builder: overlapping fluid bodies place each lattice point once", "[scene]") {
  const double dx = 0.05;
  Config c = config(2, dx);
  const std::string two = R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 1]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [0.6, 0.4]}
    - shape: {type: box, lo: [0.3, 0], hi: [1, 0.7]}
      velocity: [1, 0]
)yaml";
  const std::string one = R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 1]}
  fluid:
    - shape:
        type: union
        shapes:
          - {type: box, lo: [0, 0], hi: [0.6, 0.4]}
          - {type: box, lo: [0.3, 0], hi: [1, 0.7]}
)yaml";
  const auto a = build_scene<2>(read(two, 2), c);
  const auto b = build_scene<2>(read(one, 2), c);
  CHECK(a.particles.n_fluid == 12u * 8u + 14u * 14u - 6u * 8u);
  CHECK(a.particles.n_fluid == b.particles.n_fluid);
  CHECK(a.fluid_counts == std::vector<std::size_t>{96u, 14u * 14u - 6u * 8u});
  std::set<std::pair<long, long>> seen;
  for (std::size_t i = 0; i < a.particles.n_fluid; ++i)
    CHECK(seen.insert({std::lround(a.particles.x[0][i] / dx), std::lround(a.particles.x[1][i] / dx)}).second);
  // The overlap belongs to the first body: at rest.
  for (std::size_t i = 0; i < 96u; ++i) CHECK(a.particles.v[0][i] == 0.0);
  for (std::size_t i = 96u; i < a.particles.n_fluid; ++i) CHECK(a.particles.v[0][i] == 1.0);
}

TEST_CASE("scene builder: a closed OFF mesh cube makes the same wall body as the box", "[scene][cgal]") {
  const auto path = std::filesystem::temp_directory_path() / ("sphmol-scene-builder-" + std::to_string(::getpid()) + ".off");
  {
    std::ofstream f(path);
    f << "OFF\n8 6 0\n0.3 0.3 0.3\n0.7 0.3 0.3\n0.7 0.7 0.3\n0.3 0.7 0.3\n0.3 0.3 0.7\n0.7 0.3 0.7\n0.7 0.7 0.7\n0.3 0.7 0.7\n"
      << "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n";
  }
  Config c = config(3, 0.05);
  const std::string head = "scene:\n  domain: {lo: [0, 0, 0], hi: [1, 1, 1]}\n  fluid:\n    - shape: {type: box, lo: [0, 0, 0], hi: [1, 1, 1]}\n"
                           "  walls:\n    - shape: ";
  const auto m = build_scene<3>(read(head + "{type: mesh, file: " + path.string() + "}\n", 3), c);
  const auto b = build_scene<3>(read(head + "{type: box, lo: [0.3, 0.3, 0.3], hi: [0.7, 0.7, 0.7]}\n", 3), c);
  REQUIRE(m.particles.size() == b.particles.size());
  CHECK(m.particles.n_fluid == b.particles.n_fluid);
  // Removed: the 8^3 points of the cube and none outside (the faces lie on cell boundaries, dx/2 away).
  CHECK(m.particles.n_fluid == 8000u - 512u);
  for (std::size_t i = 0; i < m.particles.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      CHECK(m.particles.x[d][i] == b.particles.x[d][i]);
      CHECK(m.particles.wall_normal[d][i] == Approx(b.particles.wall_normal[d][i]).margin(1e-6));
    }
  std::filesystem::remove(path);
}

TEST_CASE("scene builder: a mesh read in single precision makes the same particles as the exact one", "[scene][cgal]") {
  // Binary STL and most PLY files hold float coordinates: a face meant at 0.06 is at 0.0599999986,
  // which put the lattice points half a spacing from it inside the removal band (a lost fluid layer).
  const auto write = [](const std::string& name, bool single) {
    const auto path = std::filesystem::temp_directory_path() / ("sphmol-scene-float-" + std::to_string(::getpid()) + name);
    std::ofstream f(path);
    f.precision(17);
    const double lo[3] = {0.14, 0.06, 0.04}, hi[3] = {0.26, 0.14, 0.12};
    f << "OFF\n8 6 0\n";
    for (int k = 0; k < 8; ++k)
      for (int d = 0; d < 3; ++d) {
        const double x = (k >> d & 1) ? hi[d] : lo[d];
        f << (single ? static_cast<double>(static_cast<float>(x)) : x) << (d == 2 ? "\n" : " ");
      }
    f << "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 1 3 7 5\n4 0 4 6 2\n";
    return path;
  };
  const auto exact = write("exact.off", false), single = write("single.off", true);
  Config c = config(3, 0.02);
  const std::string head = "scene:\n  domain: {lo: [0, 0, 0], hi: [0.4, 0.2, 0.3]}\n  fluid:\n    - shape: {type: box, lo: [0, 0, 0], "
                           "hi: [0.4, 0.2, 0.2]}\n  walls:\n    - shape: ";
  const auto a = build_scene<3>(read(head + "{type: mesh, file: " + exact.string() + "}\n", 3), c);
  const auto b = build_scene<3>(read(head + "{type: mesh, file: " + single.string() + "}\n", 3), c);
  const auto box = build_scene<3>(read(head + "{type: box, lo: [0.14, 0.06, 0.04], hi: [0.26, 0.14, 0.12]}\n", 3), c);
  CHECK(a.particles.n_fluid == box.particles.n_fluid);
  CHECK(b.particles.n_fluid == box.particles.n_fluid);
  CHECK(b.particles.size() == box.particles.size());
  // A fluid body that fills the domain exactly in single precision is inside it.
  const std::string fill = "scene:\n  domain: {lo: [0, 0, 0], hi: [0.14, 0.06, 0.04]}\n  fluid:\n    - shape: {type: mesh, file: ";
  std::filesystem::path whole = write("whole.off", true);
  {
    std::ofstream f(whole);
    f.precision(17);
    f << "OFF\n8 6 0\n";
    const double hi[3] = {0.14, 0.06, 0.04};
    for (int k = 0; k < 8; ++k)
      for (int d = 0; d < 3; ++d) f << ((k >> d & 1) ? static_cast<double>(static_cast<float>(hi[d])) : 0.0) << (d == 2 ? "\n" : " ");
    f << "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 1 3 7 5\n4 0 4 6 2\n";
  }
  CHECK(build_scene<3>(read(fill + whole.string() + "}\n", 3), c).particles.n_fluid == 7u * 3u * 2u);
  for (const auto& p : {exact, single, whole}) std::filesystem::remove(p);
}

TEST_CASE("scene builder: a fluid body is outside the domain only where its lattice points are", "[scene]") {
  Config c = config(3, 0.02);
  // A cylinder standing on the floor (its box was padded by the radius along the axis too).
  const auto s = build_scene<3>(read("scene:\n  domain: {lo: [0, 0, 0], hi: [0.4, 0.2, 0.3]}\n  fluid:\n    - shape: {type: cylinder, "
                                     "start: [0.2, 0.1, 0], end: [0.2, 0.1, 0.16], radius: 0.08}\n",
                                     3),
                                c);
  CHECK(s.particles.n_fluid > 0u);
  // A difference whose first part reaches out, with the part outside taken away: inside the domain.
  Config c2 = config(2, 0.1);
  const std::string d = "scene:\n  domain: {lo: [0, 0], hi: [1, 1]}\n  fluid:\n    - shape: ";
  CHECK(error_of(d + "{type: difference, shapes: [{type: box, lo: [0, 0], hi: [1.5, 0.5]}, {type: box, lo: [1, -1], hi: [2, 2]}]}\n",
                 c2) == "<no error>");
  CHECK(error_of(d + "{type: difference, shapes: [{type: box, lo: [0, 0], hi: [1.5, 0.5]}, {type: box, lo: [1.2, -1], hi: [2, 2]}]}\n",
                 c2) == "scene.yaml:4: scene.fluid[0].shape: the fluid body extends outside the domain along x (0 to 1.5 m; domain 0 to 1 m)");
}

TEST_CASE("scene builder: hydrostatic initial pressure is rho0 g depth below a surface dx/2 above the top row", "[scene]") {
  const double dx = 0.05, g = 9.81;
  for (const std::string eos : {"linear_relative", "tait"}) {
    Config c = config(2, dx);
    c.fluid.eos.type = eos;
    c.fluid.eos.gamma = 7.0;
    c.fluid.body_force = {0.0, -g};
    const auto s = build_scene<2>(read(R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 0.6], open_faces: [y_hi]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [1, 0.5]}
      pressure: hydrostatic
)yaml",
                                       2),
                                  c);
    const auto& P = s.particles;
    const double rho0 = c.fluid.density, B = c.fluid.eos.sound_speed * c.fluid.eos.sound_speed * rho0 / 7.0;
    double top = 0.0;
    for (std::size_t i = 0; i < P.n_fluid; ++i) {
      const double p = eos == "tait" ? B * (std::pow(P.rho[i] / rho0, 7.0) - 1.0) : gauge_pressure(c, P.rho[i]);
      CHECK(p == Approx(rho0 * g * (0.5 - P.x[1][i])).epsilon(1e-9));
      if (P.x[1][i] > 0.47) top = p;
    }
    CHECK(top == Approx(rho0 * g * dx / 2).epsilon(1e-9));
    // Wall particles keep the rest density.
    for (std::size_t i = P.n_fluid; i < P.size(); ++i) CHECK(P.rho[i] == rho0);
  }
}

TEST_CASE("scene builder: initial velocities and a uniform pressure from the body's keys", "[scene]") {
  Config c = config(2, 0.1);
  const auto s = build_scene<2>(read(R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 1], boundaries: [periodic, periodic]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [1, 1]}
      velocity: ["sin(2*pi*y)", "x^2 - 1"]
      pressure: 400
)yaml",
                                     2),
                                c);
  const auto& P = s.particles;
  REQUIRE(P.size() == 100u);
  CHECK(P.n_wall() == 0u);
  for (std::size_t i = 0; i < P.size(); ++i) {
    CHECK(P.v[0][i] == Approx(std::sin(2 * M_PI * P.x[1][i])));
    CHECK(P.v[1][i] == Approx(P.x[0][i] * P.x[0][i] - 1.0));
    CHECK(gauge_pressure(c, P.rho[i]) == Approx(400.0));
  }
  CHECK(s.domain.periodic[0]);
  CHECK(s.domain.periodic[1]);
  CHECK(s.fills_domain);
  CHECK_FALSE(s.open_faces);
  CHECK(s.domain.lo[0] == 0.0);
  CHECK(s.domain.hi[1] == 1.0);
}

TEST_CASE("scene builder: ghost walls mirror the closed faces and make no wall particles", "[scene]") {
  Config c = config(2, 0.1);
  c.discretization.boundary = "ghost";
  c.discretization.wall_slip = "free_slip";
  const auto s = build_scene<2>(read(R"yaml(scene:
  domain: {lo: [0, -1], hi: [2, 1], boundaries: [periodic, wall], open_faces: [y_hi]}
  fluid:
    - shape: {type: box, lo: [0, -1], hi: [2, 0.5]}
)yaml",
                                     2),
                                c);
  CHECK(s.ghost);
  CHECK(s.particles.n_wall() == 0u);
  CHECK(s.particles.n_fluid == 20u * 15u);
  CHECK_FALSE(s.walls[0][0].present);
  CHECK_FALSE(s.walls[0][1].present);
  CHECK(s.walls[1][0].present);
  CHECK(s.walls[1][0].position == -1.0);
  CHECK_FALSE(s.walls[1][0].no_slip);
  CHECK_FALSE(s.walls[1][1].present);
}

TEST_CASE("scene builder: a plane cuts the fluid (a sloping free surface) and can be a wall body", "[scene]") {
  const double dx = 0.05;
  Config c = config(2, dx);
  const auto s = build_scene<2>(read(R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 1]}
  fluid:
    - shape: {type: plane, point: [0, 0.5], normal: [1, 1]}
  walls:
    - shape: {type: plane, point: [0, 0.2], normal: [0, 1]}
)yaml",
                                     2),
                                c);
  std::size_t expected = 0;
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i) {
      const double x = (i + 0.5) * dx, y = (j + 0.5) * dx;
      expected += x + y - 0.5 < 0.0 && y - 0.2 >= 0.5 * dx - 1e-12;
    }
  CHECK(s.particles.n_fluid == expected);
  // The half-space itself is unbounded: the kit refuses to fill it uncut.
  geometry::Lattice<2> lat;
  lat.spacing = dx;
  const geometry::HalfSpaceShape<2> below({0.0, 0.2}, {0.0, 1.0});
  CHECK(below.signed_distance({3.0, 0.5}) == Approx(0.3));
  CHECK(below.bounds().hi[1] == 0.2);
  CHECK(std::isinf(below.bounds().lo[1]));
  CHECK_THROWS_WITH(geometry::fill<2>(below, lat), Catch::Contains("unbounded"));
  for (std::size_t i = s.particles.n_fluid; i < s.particles.size(); ++i)
    if (s.particles.body[i] == 0) {
      CHECK(s.particles.x[1][i] < 0.2);
      CHECK(s.particles.wall_normal[1][i] == Approx(1.0));
    }
}

TEST_CASE("scene builder: every scene that makes no sense is an error at its line", "[scene]") {
  const std::string d = "scene:\n  domain: {lo: [0, 0], hi: [1, 1]}\n  fluid:\n    - shape: ";
  const std::string fluid = d + "{type: box, lo: [0, 0], hi: [1, 0.5]}\n";
  Config c = config(2, 0.1);
  CHECK(error_of(d + "{type: box, lo: [0, 0], hi: [1.2, 0.5]}\n", c) ==
        "scene.yaml:4: scene.fluid[0].shape: the fluid body extends outside the domain along x (0 to 1.2 m; domain 0 to 1 m)");
  CHECK(error_of(d + "{type: sphere, centre: [0.5, 0.5], radius: 0.03}\n", c) ==
        "scene.yaml:4: scene.fluid[0].shape: the fluid body holds no lattice point at the spacing 0.1 m (it is smaller than a "
        "spacing, or outside the domain)");
  CHECK(error_of(fluid + "  walls:\n    - shape: {type: box, lo: [-1, -1], hi: [2, 2]}\n", c) ==
        "scene.yaml:4: scene.fluid[0].shape: every lattice point of the fluid body lies in an earlier fluid body or in a wall body");
  CHECK_THAT(error_of(fluid + "  walls:\n    - shape: {type: box, lo: [2, 0], hi: [3, 1]}\n", c),
             Catch::Equals("scene.yaml:6: scene.walls[0].shape: the wall body lies outside the domain along x"));
  CHECK(error_of("scene:\n  domain: {lo: [0, 0], hi: [1, 1], boundaries: [periodic, wall]}\n  fluid:\n    - shape: "
                 "{type: box, lo: [0, 0], hi: [1, 0.5]}\n  walls:\n    - shape: {type: box, lo: [-0.1, 0.6], hi: [0.3, 0.8]}\n",
                 c) ==
        "scene.yaml:6: scene.walls[0].shape: the wall body reaches across the periodic axis x (its extent must lie inside the "
        "domain's 0 to 1 there)");
  CHECK(error_of("scene:\n  domain: {lo: [0, 0], hi: [1.05, 1], boundaries: [periodic, open]}\n  fluid:\n    - shape: "
                 "{type: box, lo: [0, 0], hi: [1, 0.5]}\n",
                 c) ==
        "scene.yaml:2: scene.domain.hi: the domain length along x (1.05 m) is not a whole number of the spacing 0.1 m (a periodic "
        "axis needs one, so the lattice meets the faces half a spacing inside)");
  // An open axis needs no whole number of spacings.
  CHECK(error_of("scene:\n  domain: {lo: [0, 0], hi: [1, 1.05], boundaries: [wall, open]}\n  fluid:\n    - shape: "
                 "{type: box, lo: [0, 0], hi: [1, 0.5]}\n",
                 c) == "<no error>");
  {
    Config g = c;
    g.discretization.boundary = "ghost";
    CHECK(error_of(fluid + "  walls:\n    - shape: {type: sphere, centre: [0.5, 0.8], radius: 0.1}\n", g) ==
          "scene.yaml:6: scene.walls[0].shape: discretization.boundary: ghost mirrors only planes (the domain's faces and plane "
          "wall bodies); a sphere body needs discretization.boundary: wall_particles");
    g.discretization.boundary = "virtual_repulsive";
    CHECK(error_of(fluid, g) ==
          "scene.yaml:2: scene.domain: the scene builds its walls from wall particles or ghost mirrors; discretization.boundary: "
          "virtual_repulsive is not available for it");
  }
  CHECK(error_of(d + "{type: box, lo: [0, 0], hi: [1, 0.5]}\n      pressure: hydrostatic\n", c) ==
        "scene.yaml:5: scene.fluid[0].pressure: hydrostatic pressure needs a body force (fluid.body_force)");
  CHECK(error_of(d + "{type: box, lo: [0, 0], hi: [1, 0.5]}\n      pressure: -1e9\n", c) ==
        "scene.yaml:5: scene.fluid[0].pressure: the pressure -1e+09 Pa needs a negative density under the linear EOS");
  CHECK(error_of(d + "{type: box, lo: [0, 0], hi: [1, 0.5]}\n      velocity: [\"1/(x-x)\", 0]\n", c) ==
        "scene.yaml:4: scene.fluid[0].shape: the velocity expression '1/(x-x)' is not finite at a particle");
  {
    Config a = c;
    a.discretization.spacing = 0.0;
    a.discretization.particles_across = 7;
    CHECK(error_of("scene:\n  domain: {lo: [0, 0], hi: [1, 0.5]}\n  fluid:\n    - shape: {type: box, lo: [0, 0], hi: [1, 0.25]}\n", a) ==
          "scene.yaml:2: scene.domain.hi: the domain length along y (0.5 m) is not a whole number of the spacing 0.142857 m (a wall "
          "axis needs one, so the lattice meets the faces half a spacing inside)");
  }
}

TEST_CASE("scene builder: a hexagonal fluid body has the hexagonal lattice's mass and rows", "[scene]") {
  const double dx = 0.02, row = dx * std::sqrt(3.0) / 2.0;
  Config c = config(2, dx);
  const std::string scene = R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 1], boundaries: [periodic, wall]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [1, 1]}
      lattice: hexagonal
)yaml";
  const auto s = build_scene<2>(read(scene, 2), c);
  const auto& P = s.particles;
  // The first row half a spacing above the floor, as on the cubic lattice; rows up to dx/2 below the
  // top wall: 0.01 + 56 row <= 0.99.
  std::map<long, std::size_t> rows;
  for (std::size_t i = 0; i < P.n_fluid; ++i) ++rows[std::lround((P.x[1][i] - 0.5 * dx) / row)];
  REQUIRE(rows.size() == 57u);
  CHECK(rows.begin()->first == 0);
  for (const auto& [j, n] : rows) CHECK(n == 50u);
  double ymin = 1.0;
  for (std::size_t i = 0; i < P.n_fluid; ++i) ymin = std::min(ymin, P.x[1][i]);
  CHECK(ymin == Approx(0.5 * dx));
  // Summation density on the infinite lattice is rho0: the mass is close to rho0 times the cell area.
  CHECK(P.mass[0] == Approx(c.fluid.density * dx * row).epsilon(0.01));
  CHECK(P.mass[0] == hexagonal_particle_mass(c.discretization.kernel, c.fluid.density, dx, c.discretization.smoothing_ratio * dx));
  // With discretization.particle_mass: gradient the hexagonal body gets the hexagonal gradient mass
  // (scenes/lattice_mass.hpp), the wall particles the cubic one.
  {
    Config g = c;
    g.discretization.density = "continuity";
    g.discretization.particle_mass = "gradient";
    const auto sg = build_scene<2>(read(scene, 2), g);
    const double h = g.discretization.smoothing_ratio * dx;
    CHECK(sg.particles.mass[0] == hexagonal_gradient_mass(g.discretization.kernel, g.fluid.density, dx, h));
    CHECK(sg.particles.mass[0] != P.mass[0]);
    CHECK(sg.particles.mass.back() == lattice_gradient_mass<2>(g.discretization.kernel, g.fluid.density, dx, h));
    CHECK(sg.particles.kind.back() == Kind::Wall);
  }
  // Periodic along y, the staggered rows cannot continue across a length of 1.
  CHECK_THAT(error_of(R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 1], boundaries: [periodic, periodic]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [1, 1]}
      lattice: hexagonal
)yaml", c),
             Catch::StartsWith("scene.yaml:5: scene.fluid[0].lattice: a periodic y axis needs an even number of hexagonal rows"));
}

TEST_CASE("scene case: the loader reads the scene section and reports its errors at their lines", "[scene][config]") {
  const std::string base = R"yaml(case: scene
dimension: 2
fluid:
  density: 1000
  kinematic_viscosity: 1.0e-6
  eos: {sound_speed: 10}
scene:
  domain: {lo: [0, 0], hi: [1, 1]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [1, 0.5]}
  walls:
    - shape: {type: sphere, centre: [0.5, 0.8], radius: 0.1}
discretization:
  spacing: 0.1
time:
  t_end: 0.1
)yaml";
  const auto error = [&](const std::vector<std::string>& overrides, const std::string& text) {
    try {
      (void)load_config_string(text, overrides, "case.yaml");
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("<no error>");
  };
  const Config c = load_config_string(base, {}, "case.yaml");
  CHECK(c.case_name == "scene");
  CHECK(c.settings<SceneSettings>().spec.walls.size() == 1u);
  // The resolved config carries the scene and loads back to the same text.
  const std::string yaml = to_yaml(c);
  CHECK_THAT(yaml, Catch::Contains("scene:\n  domain:\n    lo: [0, 0]"));
  const auto body = [](const std::string& t) { return t.substr(t.find('\n')); };  // past the header naming the file
  CHECK(body(to_yaml(load_config_string(yaml, {}, "resolved.yaml"))) == body(yaml));
  CHECK(error({"discretization.boundary=virtual_repulsive", "discretization.repulsive.strength=1"}, base) ==
        "--set discretization.boundary=virtual_repulsive: discretization.boundary: a scene's walls are wall particles or ghost "
        "mirrors (wall_particles or ghost)");
  CHECK_THAT(error({"discretization.boundary=ghost"}, base),
             Catch::StartsWith("--set discretization.boundary=ghost: discretization.boundary: ghost mirrors only planes (the "
                               "domain's faces and plane wall bodies); the scene's wall body wall0 (case.yaml:12: "
                               "scene.walls[0].shape) is a sphere and needs wall_particles"));
  CHECK(error({"discretization.spacing=0.3"}, base) ==
        "case.yaml:8: scene.domain.hi: the domain length along x (1 m) is not a whole number of the spacing 0.3 m (a wall axis "
        "needs one, so the lattice meets the faces half a spacing inside)");
  CHECK(error({"discretization.transport_velocity.enabled=true"}, base) ==
        "--set discretization.transport_velocity.enabled=true: discretization.transport_velocity: needs a confined liquid; this "
        "scene has a free surface (an open face, or fluid that does not fill the domain)");
  CHECK_THAT(error({}, base.substr(0, base.find("scene:")) + "discretization:\n  spacing: 0.1\ntime:\n  t_end: 0.1\n"),
             Catch::Contains("scene: required value missing"));  // A start pressure sets only the continuity density; with a summed density a notice says it has no effect.
  {
    std::string with_pressure = base;
    with_pressure.replace(with_pressure.find("hi: [1, 0.5]}\n"), 14, "hi: [1, 0.5]}\n      pressure: 100\n");
    const auto said = [](const Config& k) {
      return std::count_if(k.notices.begin(), k.notices.end(),
                           [](const std::string& n) { return n.find("scene.fluid[0].pressure: has no effect") != std::string::npos; });
    };
    CHECK(said(load_config_string(with_pressure, {}, "case.yaml")) == 1);
    CHECK(said(load_config_string(with_pressure, {"discretization.density=continuity"}, "case.yaml")) == 0);
    CHECK(said(c) == 0);
  }
}

TEST_CASE("scene builder: a rotating cylinder's wall particles carry omega x r at their surface point", "[scene][motion]") {
  const double dx = 0.02, omega = 2.0, R = 0.15;
  Config c = config(2, dx);
  const auto s = build_scene<2>(read(R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 1]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [1, 1]}
  walls:
    - name: stirrer
      shape: {type: sphere, centre: [0.5, 0.4], radius: 0.15}
      motion: {type: rotation, centre: [0.5, 0.4], angular_velocity: 2}
)yaml",
                                     2),
                                c);
  const auto& P = s.particles;
  REQUIRE(P.motions.size() == 1u);
  std::size_t body = 0;
  for (std::size_t i = P.n_fluid; i < P.size(); ++i) {
    if (P.body[i] != 0) {
      CHECK(P.motion[i] == -1);  // the domain's walls stay at rest
      CHECK(P.v[0][i] == 0.0);
      CHECK(P.v[1][i] == 0.0);
      continue;
    }
    ++body;
    CHECK(P.motion[i] == 0);
    // The surface point x + depth n lies on the circle; its velocity is omega (-r_y, r_x).
    const double sx = P.x[0][i] + P.wall_depth[i] * P.wall_normal[0][i] - 0.5;
    const double sy = P.x[1][i] + P.wall_depth[i] * P.wall_normal[1][i] - 0.4;
    CHECK(std::hypot(sx, sy) == Approx(R).epsilon(1e-9));
    CHECK(P.v[0][i] == Approx(-omega * sy).margin(1e-12));
    CHECK(P.v[1][i] == Approx(omega * sx).margin(1e-12));
    // A quarter turn later the particle has turned by omega t about the centre.
    const double t = 0.25;
    const auto st = P.wall_state(i, t);
    const double rx = P.x_ref[0][i] - 0.5, ry = P.x_ref[1][i] - 0.4;
    CHECK(st.x[0] == Approx(0.5 + std::cos(omega * t) * rx - std::sin(omega * t) * ry).margin(1e-12));
    CHECK(st.x[1] == Approx(0.4 + std::sin(omega * t) * rx + std::cos(omega * t) * ry).margin(1e-12));
    CHECK(std::hypot(st.v[0], st.v[1]) == Approx(omega * R).epsilon(1e-9));
  }
  CHECK(body > 0u);
  CHECK(P.max_wall_speed() == Approx(omega * R).epsilon(1e-9));
}

TEST_CASE("scene builder: a stationary rotation keeps the cylinder in place", "[scene][motion]") {
  Config c = config(2, 0.02);
  const auto s = build_scene<2>(read(R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 1]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [1, 1]}
  walls:
    - shape: {type: sphere, centre: [0.5, 0.5], radius: 0.15}
      motion: {type: rotation, centre: [0.5, 0.5], angular_velocity: -3, stationary: true}
)yaml",
                                     2),
                                c);
  const auto& P = s.particles;
  for (std::size_t i = P.n_fluid; i < P.size(); ++i) {
    if (P.body[i] != 0) continue;
    const auto st = P.wall_state(i, 0.7);
    CHECK(st.x[0] == P.x_ref[0][i]);
    CHECK(st.x[1] == P.x_ref[1][i]);
    CHECK(std::hypot(st.v[0], st.v[1]) == Approx(3.0 * 0.15).epsilon(1e-9));
  }
}

TEST_CASE("scene builder: an oscillating box's wall particles move by x_ref + A sin(2 pi f t + phase)", "[scene][motion]") {
  Config c = config(2, 0.02);
  const auto s = build_scene<2>(read(R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 1]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [1, 0.5]}
  walls:
    - name: paddle
      shape: {type: box, lo: [0.4, 0.6], hi: [0.6, 0.8]}
      motion: {type: oscillation, amplitude: [0.01, -0.005], frequency: 2, phase: 0.3}
)yaml",
                                     2),
                                c);
  const auto& P = s.particles;
  const double A[2] = {0.01, -0.005}, w = 2.0 * M_PI * 2.0, phase = 0.3, t = 0.13;
  std::size_t body = 0;
  for (std::size_t i = P.n_fluid; i < P.size(); ++i) {
    if (P.body[i] != 0) continue;
    ++body;
    const auto st = P.wall_state(i, t);
    for (int d = 0; d < 2; ++d) {
      CHECK(P.v[d][i] == Approx(A[d] * w * std::cos(phase)));  // at t = 0
      CHECK(st.x[d] == Approx(P.x_ref[d][i] + A[d] * std::sin(w * t + phase)).margin(1e-14));
      CHECK(st.v[d] == Approx(A[d] * w * std::cos(w * t + phase)).margin(1e-14));
      CHECK(st.n[d] == P.wall_normal[d][i]);
    }
  }
  CHECK(body > 0u);
}

TEST_CASE("scene builder: a pitching cylinder in 3D turns about its axis", "[scene][motion]") {
  Config c = config(3, 0.05);
  const auto s = build_scene<3>(read(R"yaml(scene:
  domain: {lo: [0, 0, 0], hi: [1, 1, 1]}
  fluid:
    - shape: {type: box, lo: [0, 0, 0], hi: [1, 1, 1]}
  walls:
    - shape: {type: cylinder, start: [0.5, 0.5, 0], end: [0.5, 0.5, 1], radius: 0.2}
      motion: {type: pitching, centre: [0.5, 0.5, 0], axis: [0, 0, 2], angle_amplitude: 0.3, frequency: 1}
)yaml",
                                     3),
                                c);
  const auto& P = s.particles;
  REQUIRE(P.motions.size() == 1u);
  CHECK(P.motions[0].axis == std::array<double, 3>{0.0, 0.0, 1.0});  // normalised
  const double t = 0.1, theta = 0.3 * std::sin(2.0 * M_PI * t);
  for (std::size_t i = P.n_fluid; i < P.size(); ++i) {
    if (P.body[i] != 0) continue;
    const auto st = P.wall_state(i, t);
    const double rx = P.x_ref[0][i] - 0.5, ry = P.x_ref[1][i] - 0.5;
    CHECK(st.x[0] == Approx(0.5 + std::cos(theta) * rx - std::sin(theta) * ry).margin(1e-12));
    CHECK(st.x[1] == Approx(0.5 + std::sin(theta) * rx + std::cos(theta) * ry).margin(1e-12));
    CHECK(st.x[2] == Approx(P.x_ref[2][i]).margin(1e-12));
  }
}

TEST_CASE("scene builder: plane bodies under boundary: ghost are mirror planes without particles", "[scene][ghost]") {
  Config c = config(2, 0.1);
  c.discretization.boundary = "ghost";
  // A raised floor at y = 0.3 (normal up), a free-slip side mirror at x = 0.8 moving along itself,
  // the domain's x faces, and a lid on the domain's top face that replaces its mirror.
  const std::string yaml = R"yaml(scene:
  domain: {lo: [0, 0], hi: [1, 1]}
  fluid:
    - shape: {type: box, lo: [0, 0], hi: [1, 0.6]}
  walls:
    - name: floor
      shape: {type: plane, point: [0, FLOOR], normal: [0, 2]}
    - name: side
      shape: {type: plane, point: [0.8, 0], normal: [-1, 0]}
      velocity: [0, 0.5]
      slip: free_slip
    - name: lid
      shape: {type: plane, point: [0.3, 1], normal: [0, -1]}
      velocity: [1, 0]
)yaml";
  const auto with_floor = [&](const std::string& y) {
    std::string t = yaml;
    t.replace(t.find("FLOOR"), 5, y);
    return t;
  };
  const auto s = build_scene<2>(read(with_floor("0.3"), 2), c);
  CHECK(s.ghost);
  CHECK(s.particles.n_wall() == 0u);
  CHECK(s.particles.n_fluid == 8u * 3u);  // x 0.05..0.75, y 0.35..0.55
  for (std::size_t i = 0; i < s.particles.n_fluid; ++i) {
    CHECK(s.particles.x[1][i] > 0.3);
    CHECK(s.particles.x[0][i] < 0.8);
  }
  REQUIRE(s.ghost_planes.size() == 3u);
  CHECK(s.ghost_planes[0].normal == std::array<double, 2>{0.0, 1.0});
  CHECK(s.ghost_planes[0].offset == Approx(0.3));
  CHECK(s.ghost_planes[0].no_slip);
  CHECK(s.ghost_planes[1].normal == std::array<double, 2>{-1.0, 0.0});
  CHECK(s.ghost_planes[1].offset == Approx(-0.8));
  CHECK_FALSE(s.ghost_planes[1].no_slip);
  CHECK(s.ghost_planes[1].velocity == std::array<double, 2>{0.0, 0.5});
  CHECK(s.ghost_planes[2].velocity == std::array<double, 2>{1.0, 0.0});
  CHECK(s.body_names == std::vector<std::string>{"floor", "side", "lid"});
  CHECK(s.particles.body_treatment == std::vector<WallTreatment>{WallTreatment::ghost, WallTreatment::ghost, WallTreatment::ghost});
  CHECK(s.walls[1][0].present);        // the lower face stays a mirror: 0.3 m below the floor, beyond the support
  CHECK_FALSE(s.walls[1][1].present);  // the lid replaces the top face's mirror
  CHECK_FALSE(s.open_faces);
  // A floor one spacing above the lower face with h = 2 dx (support 0.4 m): the face's images of the
  // first rows (0.3 m from them) would reach the fluid.
  Config wide = c;
  wide.discretization.smoothing_ratio = 2.0;
  CHECK(error_of(with_floor("0.1"), wide) ==
        "scene.yaml:7: scene.walls[0].shape: this ghost mirror and the domain's lower y face face the same way 0.1 m apart: "
        "the images of the one behind would reach the fluid of the other (2 gap + dx = 0.3 m within the kernel support, 0.4 m); "
        "open that face or move the plane");
  CHECK(error_of(with_floor("0.2"), wide) == "<no error>");
}

TEST_CASE("scene builder: ghost planes in 3D, along an axis and oblique, and their checks", "[scene][ghost][3d]") {
  Config c = config(3, 0.1);
  c.discretization.boundary = "ghost";
  const std::string head = "scene:\n  domain: {lo: [0, 0, 0], hi: [1, 1, 1], boundaries: [open, open, open]}\n"
                           "  fluid:\n    - shape: {type: box, lo: [0, 0, 0], hi: [1, 1, 0.5]}\n  walls:\n";
  // A floor tilted about the y axis, a side plane at right angles to it (its normal in the x-z plane,
  // perpendicular to the floor's) and one along y: all pairwise at right angles.
  const double c30 = std::cos(M_PI / 6), s30 = std::sin(M_PI / 6);
  std::ostringstream w;
  w.precision(15);
  w << "    - shape: {type: plane, point: [0.5, 0.5, 0.2], normal: [" << -s30 << ", 0, " << c30 << "]}\n"
    << "    - shape: {type: plane, point: [0.1, 0.5, 0.3], normal: [" << c30 << ", 0, " << s30 << "]}\n"
    << "    - shape: {type: plane, point: [0.5, 0.1, 0.3], normal: [0, 1, 0]}\n";
  const auto s = build_scene<3>(read(head + w.str(), 3), c);
  CHECK(s.particles.n_wall() == 0u);
  REQUIRE(s.ghost_planes.size() == 3u);
  CHECK(s.ghost_planes[0].normal[0] == Approx(-s30));
  CHECK(s.ghost_planes[0].normal[2] == Approx(c30));
  CHECK(s.ghost_planes[0].offset == Approx(-s30 * 0.5 + c30 * 0.2));
  for (std::size_t i = 0; i < s.particles.n_fluid; ++i)
    for (const auto& p : s.ghost_planes) {
      double d = -p.offset;
      for (int k = 0; k < 3; ++k) d += p.normal[k] * s.particles.x[k][i];
      CHECK(d >= 0.05 - 1e-9);  // every fluid particle half a spacing or more on the fluid side
    }
  // A plane at 30 degrees to the y plane is refused where the fluid reaches both.
  CHECK_THAT(error_of(head + "    - shape: {type: plane, point: [0.5, 0.1, 0.3], normal: [0, 1, 0]}\n"
                             "    - shape: {type: plane, point: [0.5, 0.5, 0.3], normal: [0, " +
                          std::to_string(-c30) + ", " + std::to_string(s30) + "]}\n",
                      c),
             Catch::Contains("scene.walls[1].shape: this ghost mirror and the ghost mirror at scene.yaml:6: scene.walls[0].shape meet at "
                      "30 degrees"));
}
