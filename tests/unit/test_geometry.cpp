// The geometry kit: signed distances of the shapes (exact values at chosen points), boolean
// combinations, lattice fills (counts and areas/volumes), the CGAL polygon and triangle-mesh shapes,
// and wall layers — including the box container against the wall particles of the box scene.
#include <catch2/catch.hpp>

#include <sys/resource.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <filesystem>
#include <fstream>
#include <map>
#include <tuple>
#include <unistd.h>

#include "sphmol/config/config.hpp"
#include "sphmol/geometry/box_shape.hpp"
#include "sphmol/geometry/cylinder_shape.hpp"
#include "sphmol/geometry/lattice.hpp"
#include "sphmol/geometry/polygon_shape.hpp"
#include "sphmol/geometry/shape_algebra.hpp"
#include "sphmol/geometry/sphere_shape.hpp"
#include "sphmol/geometry/triangle_mesh_shape.hpp"
#include "sphmol/geometry/wall_layers.hpp"
#include "sphmol/scenes/box_scene.hpp"

using namespace sphmol::geometry;

TEST_CASE("geometry: box signed distance is exact inside, outside and at corners", "[geometry]") {
  const BoxShape<2> b({0.0, 0.0}, {2.0, 1.0});
  CHECK(b.signed_distance({1.0, 0.5}) == Approx(-0.5));
  CHECK(b.signed_distance({0.1, 0.5}) == Approx(-0.1));
  CHECK(b.signed_distance({3.0, 0.5}) == Approx(1.0));
  CHECK(b.signed_distance({3.0, 2.0}) == Approx(std::sqrt(2.0)));  // beyond the corner
  CHECK(b.signed_distance({2.0, 0.5}) == Approx(0.0).margin(1e-15));
  CHECK_THROWS_AS(BoxShape<2>({0.0, 0.0}, {0.0, 1.0}), std::invalid_argument);
  const BoxShape<3> c({0, 0, 0}, {1, 1, 1});
  CHECK(c.signed_distance({0.5, 0.5, 0.9}) == Approx(-0.1));
  CHECK(c.signed_distance({2, 2, 2}) == Approx(std::sqrt(3.0)));
}

TEST_CASE("geometry: sphere, cylinder and their outward normals", "[geometry]") {
  const SphereShape<3> s({1, 1, 1}, 0.5);
  CHECK(s.signed_distance({1, 1, 1}) == Approx(-0.5));
  CHECK(s.signed_distance({1, 1, 2}) == Approx(0.5));
  const auto n = s.outward_normal({1.0, 1.3, 1.0}, 1e-7);
  CHECK(n[1] == Approx(1.0));
  CHECK(n[0] == Approx(0.0).margin(1e-6));
  const CylinderShape cyl({0, 0, 0}, {0, 0, 2}, 1.0);
  CHECK(cyl.signed_distance({0, 0, 1}) == Approx(-1.0));      // on the axis, mid-height: the side is nearest
  CHECK(cyl.signed_distance({0, 0, 0.25}) == Approx(-0.25));  // near the bottom cap
  CHECK(cyl.signed_distance({2, 0, 1}) == Approx(1.0));
  CHECK(cyl.signed_distance({2, 0, 3}) == Approx(std::sqrt(2.0)));  // beyond the rim
  const auto nc = cyl.outward_normal({0.0, 0.9, 1.0}, 1e-7);
  CHECK(nc[1] == Approx(1.0));
}

TEST_CASE("geometry: a cylinder's box is tight along and across its axis", "[geometry]") {
  // Standing on z = 0: its box must not reach below the floor (a fluid body standing there was
  // refused as outside the domain).
  const auto b = CylinderShape({0.2, 0.1, 0.0}, {0.2, 0.1, 0.15}, 0.08).bounds();
  CHECK(b.lo[2] == 0.0);
  CHECK(b.hi[2] == 0.15);
  CHECK(b.lo[0] == Approx(0.12));
  CHECK(b.hi[1] == Approx(0.18));
  // Tilted: each cap reaches r sqrt(1 - a_d^2) along axis d; every surface point lies in the box, and
  // the box touches the surface (to the sampling).
  const Vec<3> a{0.0, 0.0, 0.0}, e{1.0, 2.0, 2.0};
  const double r = 0.5;
  const CylinderShape c(a, e, r);
  const auto t = c.bounds();
  const Vec<3> ax{1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};
  const Vec<3> u{2.0 / 3.0, -2.0 / 3.0, 1.0 / 3.0}, w{2.0 / 3.0, 1.0 / 3.0, -2.0 / 3.0};  // unit, orthogonal to ax
  Vec<3> lo{1e9, 1e9, 1e9}, hi{-1e9, -1e9, -1e9};
  for (const Vec<3>& end : {a, e})
    for (int k = 0; k < 3600; ++k) {
      const double phi = 2.0 * M_PI * k / 3600.0;
      for (int d = 0; d < 3; ++d) {
        const double x = end[d] + r * (std::cos(phi) * u[d] + std::sin(phi) * w[d]);
        lo[d] = std::min(lo[d], x);
        hi[d] = std::max(hi[d], x);
      }
    }
  for (int d = 0; d < 3; ++d) {
    CHECK(t.lo[d] <= lo[d] + 1e-12);
    CHECK(t.hi[d] >= hi[d] - 1e-12);
    CHECK(t.lo[d] == Approx(lo[d]).margin(1e-6));
    CHECK(t.hi[d] == Approx(hi[d]).margin(1e-6));
    CHECK(t.hi[d] - t.lo[d] == Approx(e[d] + 2.0 * r * std::sqrt(1.0 - ax[d] * ax[d])));
  }
}

TEST_CASE("geometry: union, intersection and difference keep the exact inside test", "[geometry]") {
  const ShapePtr<2> a = std::make_shared<BoxShape<2>>(Vec<2>{0, 0}, Vec<2>{2, 2});
  const ShapePtr<2> hole = std::make_shared<SphereShape<2>>(Vec<2>{1, 1}, 0.5);
  const auto ring = subtract<2>(a, hole);
  CHECK(ring->contains({0.2, 0.2}));
  CHECK_FALSE(ring->contains({1.0, 1.0}));
  CHECK(ring->signed_distance({1.0, 1.0}) == Approx(0.5));  // distance out of the hole's surface
  const auto both = unite<2>({a, std::make_shared<BoxShape<2>>(Vec<2>{3, 0}, Vec<2>{4, 1})});
  CHECK(both->contains({3.5, 0.5}));
  CHECK_FALSE(both->contains({2.5, 0.5}));
  CHECK(both->bounds().hi[0] == 4.0);
  const auto lens = intersect<2>(a, std::make_shared<SphereShape<2>>(Vec<2>{2, 2}, 1.0));
  CHECK(lens->contains({1.8, 1.8}));
  CHECK_FALSE(lens->contains({2.5, 2.5}));
}

TEST_CASE("geometry: lattice fill of a box holds exactly L/dx points per axis at cell centres", "[geometry]") {
  Lattice<2> lat;
  lat.spacing = 0.1;
  const auto pts = fill<2>(BoxShape<2>({0, 0}, {1.0, 0.5}), lat);
  REQUIRE(pts.size() == 50u);
  CHECK(pts.front()[0] == Approx(0.05));
  CHECK(pts.front()[1] == Approx(0.05));
  CHECK(pts[1][0] == Approx(0.15));  // x fastest, as the particle arrays of the box scenes
  Lattice<3> lat3;
  lat3.spacing = 0.25;
  CHECK(fill<3>(BoxShape<3>({0, 0, 0}, {1, 0.5, 0.75}), lat3).size() == 4u * 2u * 3u);
}

TEST_CASE("geometry: filled area and volume converge to the shape's", "[geometry]") {
  for (const double dx : {0.02, 0.01}) {
    Lattice<2> lat;
    lat.spacing = dx;
    const double area = fill<2>(SphereShape<2>({0.5, 0.5}, 0.3), lat).size() * lat.cell_volume();
    CHECK(area == Approx(M_PI * 0.09).epsilon(2.0 * dx));
    lat.type = LatticeType::hexagonal;
    const double hex = fill<2>(SphereShape<2>({0.5, 0.5}, 0.3), lat).size() * lat.cell_volume();
    CHECK(hex == Approx(M_PI * 0.09).epsilon(2.0 * dx));
  }
  Lattice<3> lat3;
  lat3.spacing = 0.02;
  const double vol = fill<3>(CylinderShape({0, 0, 0}, {0, 0, 1}, 0.25), lat3).size() * lat3.cell_volume();
  CHECK(vol == Approx(M_PI * 0.0625).epsilon(0.03));
  Lattice<3> hex3;
  hex3.spacing = 0.1;
  hex3.type = LatticeType::hexagonal;
  CHECK_THROWS_AS(fill<3>(BoxShape<3>({0, 0, 0}, {1, 1, 1}), hex3), std::invalid_argument);
}

TEST_CASE("geometry: polygon (CGAL) inside test and distance, in either orientation", "[geometry][cgal]") {
  const std::vector<Vec<2>> l_shape{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (const bool reverse : {false, true}) {
    auto v = l_shape;
    if (reverse) std::reverse(v.begin(), v.end());
    const PolygonShape p(v);
    CHECK(p.signed_distance({0.5, 0.5}) == Approx(-0.5));
    CHECK(p.signed_distance({1.5, 1.5}) == Approx(0.5));  // in the notch, half way to both inner edges
    CHECK(p.signed_distance({3.0, 3.0}) == Approx(std::sqrt(5.0)));  // as far from the vertices (1, 2) and (2, 1)
    CHECK(p.signed_distance({1.5, 0.9}) == Approx(-0.1));
  }
  Lattice<2> lat;
  lat.spacing = 0.1;
  CHECK(fill<2>(PolygonShape(l_shape), lat).size() == 300u);  // area 3 / 0.01, no point on an edge
  // Lattice points on an edge in decimal: the exact side test decides, in either orientation. The
  // rounded distance of such a point can be 0 in one orientation only, which read as outside there.
  const std::vector<Vec<2>> tri{{0.1, 0.05}, {0.2, 0.15}, {0.3, 0.05}};
  const std::vector<Vec<2>> tri_cw{{0.3, 0.05}, {0.2, 0.15}, {0.1, 0.05}};
  const PolygonShape ccw(tri), cw(tri_cw);
  Lattice<2> fine;
  fine.spacing = 0.01;
  Bounds<2> region;
  region.lo = {0.0, 0.0};
  region.hi = {0.4, 0.2};
  std::size_t inside = 0;
  fine.for_each_in(region, [&](const Vec<2>& q) {
    INFO(q[0] << " " << q[1]);
    CHECK(ccw.contains(q) == cw.contains(q));
    CHECK(std::signbit(ccw.signed_distance(q)) == std::signbit(cw.signed_distance(q)));
    inside += ccw.contains(q);
  });
  CHECK(inside > 0u);
  CHECK_THROWS_AS(PolygonShape({{0, 0}, {1, 1}, {1, 0}, {0, 1}}), std::invalid_argument);  // a bow tie
  CHECK_THROWS_AS(PolygonShape({{0, 0}, {1, 1}}), std::invalid_argument);
}

namespace {
// A cube [0, 1]^3 as an OFF file with quad faces (CGAL triangulates them).
std::string write_cube_off(const std::string& name, bool open) {
  const auto path = std::filesystem::temp_directory_path() / ("sphmol-geom-" + std::to_string(::getpid()) + "-" + name);
  std::ofstream f(path);
  f << "OFF\n8 " << (open ? 5 : 6) << " 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    << "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n";
  if (!open) f << "4 0 4 7 3\n";
  return path.string();
}
}  // namespace

TEST_CASE("geometry: triangle mesh (CGAL) read from OFF agrees with the box", "[geometry][cgal]") {
  const std::string off = write_cube_off("cube.off", false);
  const TriangleMeshShape mesh(off);
  CHECK(mesh.triangles() == 12u);
  const BoxShape<3> box({0, 0, 0}, {1, 1, 1});
  for (const Vec<3> p : {Vec<3>{0.5, 0.5, 0.5}, Vec<3>{0.1, 0.5, 0.7}, Vec<3>{1.5, 0.5, 0.5}, Vec<3>{-0.2, 1.3, 0.5},
                         Vec<3>{0.95, 0.05, 0.5}})
    CHECK(mesh.signed_distance(p) == Approx(box.signed_distance(p)).margin(1e-12));
  Lattice<3> lat;
  lat.spacing = 0.1;
  CHECK(fill<3>(mesh, lat).size() == 1000u);
  CHECK_THROWS_WITH(TriangleMeshShape(write_cube_off("open.off", true)), Catch::Contains("not closed"));
  // Two closed cubes that overlap in one file: the ray-crossing inside test would leave the overlap
  // outside; a surface that intersects itself is refused.
  {
    std::ostringstream two;
    two << "OFF\n16 12 0\n";
    for (const double o : {0.0, 0.5})
      two << o << " " << o << " " << o << "\n" << o + 1 << " " << o << " " << o << "\n" << o + 1 << " " << o + 1 << " " << o << "\n"
          << o << " " << o + 1 << " " << o << "\n" << o << " " << o << " " << o + 1 << "\n" << o + 1 << " " << o << " " << o + 1 << "\n"
          << o + 1 << " " << o + 1 << " " << o + 1 << "\n" << o << " " << o + 1 << " " << o + 1 << "\n";
    for (const int k : {0, 8})
      two << "4 " << k << " " << k + 3 << " " << k + 2 << " " << k + 1 << "\n4 " << k + 4 << " " << k + 5 << " " << k + 6 << " " << k + 7
          << "\n4 " << k << " " << k + 1 << " " << k + 5 << " " << k + 4 << "\n4 " << k + 2 << " " << k + 3 << " " << k + 7 << " " << k + 6
          << "\n4 " << k + 1 << " " << k + 2 << " " << k + 6 << " " << k + 5 << "\n4 " << k << " " << k + 4 << " " << k + 7 << " " << k + 3
          << "\n";
    CHECK_THROWS_WITH(TriangleMeshShape(two.str(), "off", "two.off"), Catch::Contains("intersects itself"));
    // Apart, the same two cubes are one closed surface with two parts, and both are inside.
    std::string apart = two.str();
    for (std::size_t at = 0; (at = apart.find("0.5", at)) != std::string::npos;) apart.replace(at, 3, "2.5"), at += 3;
    for (std::size_t at = 0; (at = apart.find("1.5", at)) != std::string::npos;) apart.replace(at, 3, "3.5"), at += 3;
    const TriangleMeshShape parts(apart, "off", "apart.off");
    CHECK(parts.contains({0.5, 0.5, 0.5}));
    CHECK(parts.contains({3.0, 3.0, 3.0}));
    CHECK_FALSE(parts.contains({2.0, 2.0, 2.0}));
  }
  CHECK_THROWS_WITH(TriangleMeshShape("/nonexistent/x.stl"), Catch::Contains("no such file"));
  std::filesystem::remove(off);
}

TEST_CASE("geometry: wall layers of a solid lie within the thickness, normals out of the solid", "[geometry]") {
  Lattice<2> lat;
  lat.spacing = 0.05;
  const SphereShape<2> cyl({0.5, 0.5}, 0.2);
  const auto w = wall_layer<2>(cyl, lat, 3 * lat.spacing);
  REQUIRE(!w.empty());
  for (const auto& p : w) {
    CHECK(p.depth > 0.0);
    CHECK(p.depth <= 3 * lat.spacing + 1e-12);
    const Vec<2> r{p.x[0] - 0.5, p.x[1] - 0.5};
    if (norm<2>(r) > 1e-9) CHECK(dot<2>(p.normal, r) / norm<2>(r) == Approx(1.0).epsilon(1e-6));  // radial
  }
  // A ring of width 3 dx: its area over the cell area, within the lattice's granularity.
  const double ring = M_PI * (0.04 - std::pow(0.2 - 0.15, 2));
  CHECK(w.size() * lat.cell_volume() == Approx(ring).epsilon(0.15));
}

TEST_CASE("geometry: box container walls equal the box scene's wall particles", "[geometry]") {
  // The driven cavity's walls (all four faces, the lid taking the corners) and the open-topped tank.
  for (const bool lid : {true, false}) {
    sphmol::Config c = sphmol::load_config_string(R"(
case: cavity
fluid: {density: 1, kinematic_viscosity: 0.01, eos: {type: linear_relative, sound_speed: 10}}
geometry: {box: [1, 1], wall_velocity: 1}
discretization: {particles_across: 10, kernel: wendland_c2, smoothing_ratio: 1.3}
time: {t_end: 0.1, integrator: leapfrog}
)");
    sphmol::BoxWalls<2> walls{};
    walls[0][0].present = walls[0][1].present = walls[1][0].present = true;
    walls[1][1].present = lid;
    const double Ly = lid ? 1.0 : 1.2;
    const auto scene = sphmol::build_box_scene(c, 1.0, Ly, 1.0, walls, false);
    const double dx = scene.spacing;
    Lattice<2> lat;
    lat.spacing = dx;
    const auto w = box_container_walls<2>({0, 0}, {1.0, Ly}, {false, false, false, !lid}, lat, scene.wall_layers * dx, 3);
    const auto& P = scene.particles;
    REQUIRE(w.size() == P.n_wall());
    // Same points with the same normals and depths (both lists in lattice order).
    std::map<std::tuple<long, long>, std::size_t> at;
    for (std::size_t k = 0; k < w.size(); ++k) at[{std::lround(w[k].x[0] / dx * 2), std::lround(w[k].x[1] / dx * 2)}] = k;
    for (std::size_t i = P.n_fluid; i < P.size(); ++i) {
      const auto it = at.find({std::lround(P.x[0][i] / dx * 2), std::lround(P.x[1][i] / dx * 2)});
      REQUIRE(it != at.end());
      const auto& q = w[it->second];
      CHECK(q.depth == Approx(P.wall_depth[i]));
      CHECK(q.normal[0] == P.wall_normal[0][i]);
      CHECK(q.normal[1] == P.wall_normal[1][i]);
    }
  }
}

TEST_CASE("geometry: triangle mesh (CGAL) read from an ASCII STL, triangles in any orientation", "[geometry][cgal]") {
  // The cube [0, 2]^3 as 12 triangles, half of them listed clockwise: the reader orients the soup.
  const auto path = std::filesystem::temp_directory_path() / ("sphmol-geom-" + std::to_string(::getpid()) + "-cube.stl");
  {
    const double v[8][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2}};
    const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    std::ofstream f(path);
    f << "solid cube\n";
    for (int q = 0; q < 6; ++q)
      for (const auto& tri : {std::array<int, 3>{quads[q][0], quads[q][1], quads[q][2]},
                              q % 2 ? std::array<int, 3>{quads[q][0], quads[q][3], quads[q][2]}  // reversed
                                    : std::array<int, 3>{quads[q][0], quads[q][2], quads[q][3]}}) {
        f << "facet normal 0 0 0\n outer loop\n";
        for (int k : tri) f << "  vertex " << v[k][0] << ' ' << v[k][1] << ' ' << v[k][2] << '\n';
        f << " endloop\nendfacet\n";
      }
    f << "endsolid cube\n";
  }
  const TriangleMeshShape mesh(path.string());
  CHECK(mesh.triangles() == 12u);
  const BoxShape<3> box({0, 0, 0}, {2, 2, 2});
  for (const Vec<3> p : {Vec<3>{1, 1, 1}, Vec<3>{0.3, 1.9, 1.2}, Vec<3>{2.5, 1, 1}, Vec<3>{-1, -1, -1}})
    CHECK(mesh.signed_distance(p) == Approx(box.signed_distance(p)).margin(1e-12));
  std::filesystem::remove(path);
}

namespace {
// The cube [0, 1]^3: 8 vertices and its 12 triangles, outward.
const double kCubeV[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const int kCubeT[12][3] = {{0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                           {2, 3, 7}, {2, 7, 6}, {1, 2, 6}, {1, 6, 5}, {0, 4, 7}, {0, 7, 3}};

void check_unit_cube(const TriangleMeshShape& mesh) {
  CHECK(mesh.triangles() == 12u);
  const BoxShape<3> box({0, 0, 0}, {1, 1, 1});
  for (const Vec<3> p : {Vec<3>{0.5, 0.5, 0.5}, Vec<3>{0.1, 0.5, 0.7}, Vec<3>{1.5, 0.5, 0.5}})
    CHECK(mesh.signed_distance(p) == Approx(box.signed_distance(p)).margin(1e-6));  // STL stores floats
}
}  // namespace

TEST_CASE("geometry: triangle meshes from binary STL, PLY and OBJ bytes", "[geometry][cgal]") {
  {
    std::string stl(80, ' ');  // header
    const auto put = [&](const void* p, std::size_t n) { stl.append(static_cast<const char*>(p), n); };
    const std::uint32_t n = 12;
    put(&n, 4);
    for (const auto& t : kCubeT) {
      const float normal[3] = {0, 0, 0};
      put(normal, sizeof normal);
      for (int k : t) {
        const float v[3] = {static_cast<float>(kCubeV[k][0]), static_cast<float>(kCubeV[k][1]), static_cast<float>(kCubeV[k][2])};
        put(v, sizeof v);
      }
      const std::uint16_t attr = 0;
      put(&attr, 2);
    }
    check_unit_cube(TriangleMeshShape(stl, "stl", "cube.stl"));
  }
  {
    std::ostringstream ply;
    ply << "ply\nformat ascii 1.0\nelement vertex 8\nproperty double x\nproperty double y\nproperty double z\n"
           "element face 12\nproperty list uchar int vertex_indices\nend_header\n";
    for (const auto& v : kCubeV) ply << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
    for (const auto& t : kCubeT) ply << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    check_unit_cube(TriangleMeshShape(ply.str(), "ply", "cube.ply"));
  }
  {
    std::ostringstream obj;
    for (const auto& v : kCubeV) obj << "v " << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
    for (const auto& t : kCubeT) obj << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    check_unit_cube(TriangleMeshShape(obj.str(), "obj", "cube.obj"));
  }
  CHECK_THROWS_WITH(TriangleMeshShape("solid x\n", "vtk", "x.vtk"), Catch::Contains("unknown format 'vtk'"));
  CHECK_THROWS_WITH(TriangleMeshShape("not a mesh at all", "off", "x.off"), Catch::Contains("cannot be read"));
  // What is wrong, where it can be said: a face past the vertices, faces without area.
  CHECK_THROWS_WITH(TriangleMeshShape("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n", "obj", "i.obj"),
                    Catch::Contains("face 0 refers to a vertex the file does not have (it has 3)"));
  CHECK_THROWS_WITH(TriangleMeshShape("OFF\n4 2 0\n1 1 1\n1 1 1\n1 1 1\n1 1 1\n3 0 1 2\n3 0 2 3\n", "off", "z.off"),
                    Catch::Contains("no face has an area"));
}

TEST_CASE("geometry: a mesh file whose header asks for more than it holds, or too large a file, is refused", "[geometry][cgal][security]") {
  // CGAL's OFF reader allocates the declared vertex and face counts before reading them: this 34-byte
  // file asked for 2e9 of each (std::bad_alloc, or gigabytes of memory for smaller counts).
  CHECK_THROWS_WITH(TriangleMeshShape("OFF\n2000000000 2000000000 0\n0 0 0\n", "off", "big.off"),
                    Catch::Contains("the header declares 2000000000 vertices and 2000000000 faces, more than a file of 34 bytes can hold"));
  CHECK_THROWS_WITH(TriangleMeshShape("OFF\n# a comment\n300000000 0 0\n", "off", "big.off"), Catch::Contains("300000000 vertices"));
  // A count with trailing characters is still read as a count by the stream (found by fuzzing).
  CHECK_THROWS_WITH(TriangleMeshShape("OFF\n 1870000100+0000 1\n0 0 0\n", "off", "c.off"), Catch::Contains("1870000100 vertices"));
  CHECK_THROWS_WITH(TriangleMeshShape("v 0 0 0\nv 1 0 0\nv 0 1e200 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n", "obj", "i.obj"),
                    Catch::Contains("not a number of magnitude up to 1e100"));
  // Binary OFF: its counts are raw integers ("3 3$" read as 0x33203324 vertices), found by fuzzing.
  CHECK_THROWS_WITH(TriangleMeshShape(std::string("OFF\x17\nBINARY\n3 3$1") + std::string(60, ' '), "off", "b.off"),
                    Catch::Contains("binary OFF is not read"));
  {
    // A face line whose count is far beyond its indices: CGAL sized the face by the count first, here
    // 3e8 indices (2.4 GB) for a 60-byte file (found by fuzzing). Refused before anything is allocated.
    rusage before{}, after{};
    getrusage(RUSAGE_SELF, &before);
    CHECK_THROWS_WITH(TriangleMeshShape("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n300000000 0 1 2\n", "off", "f.off"),
                      Catch::Contains("mesh f.off: a face declares 300000000 vertices, more than the file holds"));
    getrusage(RUSAGE_SELF, &after);
    CHECK(after.ru_maxrss - before.ru_maxrss < 100 * 1024);  // [KiB]
    // The same through a PLY list with a 32-bit count, which CGAL sizes before reading its entries.
    CHECK_THROWS_WITH(TriangleMeshShape("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                        "property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n"
                                        "0 0 0\n1 0 0\n0 1 0\n300000000 0 1 2\n",
                                        "ply", "f.ply"),
                      Catch::Contains("a list property with 'uint' counts is not read"));
    // Counts that fit are read as before: the cube's faces as one quad each side.
    std::ostringstream quads;
    quads << "OFF\n8 6 0\n";
    for (const auto& v : kCubeV) quads << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
    quads << "4 0 1 2 3\n4 4 7 6 5\n4 0 4 5 1\n4 1 5 6 2\n4 2 6 7 3\n4 3 7 4 0\n";
    CHECK_NOTHROW(TriangleMeshShape(quads.str(), "off", "quads.off"));
  }
  CHECK_THROWS_WITH(TriangleMeshShape("ply\nformat ascii 1.0\nelement vertex 1000000\nproperty float x\nend_header\n", "ply", "big.ply"),
                    Catch::Contains("declares 1000000 elements"));
  // A sparse file just above the limit: refused by its size, before anything is read.
  const auto path = std::filesystem::temp_directory_path() / ("sphmol-geom-" + std::to_string(::getpid()) + "-huge.stl");
  {
    std::ofstream f(path);
  }
  std::filesystem::resize_file(path, kMaxMeshBytes + 1);
  CHECK_THROWS_WITH(TriangleMeshShape(path.string()), Catch::Contains("larger than"));
  std::filesystem::remove(path);
}

TEST_CASE("geometry: mesh inputs that broke CGAL's readers and repair are refused or cleaned", "[geometry][cgal][security]") {
  // Found by fuzz/mesh_fuzz.cpp. A PLY property before any element: CGAL 5.5 read past an empty list.
  CHECK_THROWS_WITH(TriangleMeshShape("ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n0\n", "ply", "p.ply"),
                    Catch::Contains("a property before any element"));
  CHECK_THROWS_WITH(TriangleMeshShape("ply\nformat ascii 1.0\nelement vertex 3\n", "ply", "p.ply"), Catch::Contains("no end_header"));
  // A face that is not plane: CGAL's triangulation of its projection failed.
  std::ostringstream bent;
  bent << "OFF\n8 7 0\n";
  for (const auto& v : kCubeV) bent << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
  bent << "6 0 1 2 6 7 4\n";
  for (int t = 0; t < 6; ++t) bent << "3 " << kCubeT[t][0] << ' ' << kCubeT[t][1] << ' ' << kCubeT[t][2] << '\n';
  CHECK_THROWS_WITH(TriangleMeshShape(bent.str(), "off", "bent.off"), Catch::Contains("face 0 has 6 vertices that do not lie in one plane or do not make a convex face"));
  // The cube with a triangle of no area (three points on an edge) and one that repeats a vertex: both
  // dropped (the inside test needs proper triangles; the repair needs distinct vertices).
  std::ostringstream extra;
  extra << "OFF\n9 14 0\n";
  for (const auto& v : kCubeV) extra << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
  extra << "0.5 0 0\n";
  for (const auto& t : kCubeT) extra << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  extra << "3 0 8 1\n3 2 6 2\n";
  check_unit_cube(TriangleMeshShape(extra.str(), "off", "extra.off"));
}
