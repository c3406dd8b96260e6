// The .vtp writer on 3D systems: positions and velocities with three components, fluid, wall and
// ghost particles, decoded by the test's independent reader (vtk_appended.hpp) and equal to the
// state bit for bit.
#include <catch2/catch.hpp>

#include <cmath>

#include "mini_xml.hpp"
#include "sphmol/geometry/wall_layers.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/run/vtk_observer.hpp"
#include "sphmol/scenes/lattice_mass.hpp"
#include "vtk_appended.hpp"

using namespace sphmol;
using vtk_appended::array_named;

namespace {

struct Part {
  vtk_appended::File file;
  std::size_t n = 0;
  std::vector<double> xyz;
  const mini_xml::Element* pd = nullptr;
  const std::vector<double>& point(const std::string& name) const { return file.of(array_named(*pd, name)); }
};

Part decode(const std::string& text) {
  Part p;
  p.file = vtk_appended::read(text);
  const auto* piece = p.file.root->child("PolyData")->child("Piece");
  REQUIRE(piece);
  p.n = std::stoul(piece->attr.at("NumberOfPoints"));
  p.pd = piece->child("PointData");
  REQUIRE(p.pd);
  p.xyz = p.file.of(array_named(*piece->child("Points"), "Points"));
  REQUIRE(p.xyz.size() == 3 * p.n);
  REQUIRE(p.point("velocity").size() == 3 * p.n);
  return p;
}

// A 3D duct: fluid on a 6 x 5 x 4 lattice of spacing 0.1, periodic in x, wall particles beyond the
// faces y = 0, y = 0.5, z = 0 and z = 0.4 (box_container_walls<3>), walls moving in x at 0.2.
struct Duct {
  Particles<3> particles;
  Domain<3> domain;
  BoxWalls<3> walls{};
  double dx = 0.1;
  explicit Duct(bool wall_particles) {
    const double Lx = 0.6, Ly = 0.5, Lz = 0.4, m = lattice_particle_mass<3>("cubic_spline", 1000.0, dx, 1.3 * dx);
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 6; ++i)
          particles.add(Kind::Fluid, {(i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx},
                        {0.1 * std::sin(i + 2.0 * j), 0.05 * k, -0.03 * j}, m, 1000.0);
    if (wall_particles) {
      geometry::Lattice<3> lat;
      lat.spacing = dx;
      for (const auto& p : geometry::box_container_walls<3>({0, 0, 0}, {Lx, Ly, Lz}, {true, true, false, false, false, false},
                                                            lat, 3 * dx))
        particles.add(Kind::Wall, p.x, {0.2, 0.0, 0.0}, m, 1000.0, p.normal, p.depth);
    }
    domain.lo = {0.0, -0.4, -0.4};
    domain.hi = {Lx, Ly + 0.4, Lz + 0.4};
    domain.periodic = {true, false, false};
    walls[1][0] = {true, 0.0, true, {}};
    walls[1][1] = {true, Ly, true, {}};
    walls[2][0] = {true, 0.0, true, {}};
    walls[2][1] = {true, Lz, true, {}};
  }
};

Config duct_config(const std::string& boundary) {
  Config c;
  c.case_name = "duct";
  c.dimension = 3;
  c.fluid.density = 1000.0;
  c.fluid.kinematic_viscosity = 1e-3;
  c.fluid.eos.sound_speed = 2.0;
  c.discretization.boundary = boundary;
  if (boundary != "wall_particles") c.discretization.wall_model = "prescribed";  // Morris needs wall particles
  c.discretization.neighbor_search = "cell_list";
  return c;
}

}  // namespace

TEST_CASE("vtk 3D: fluid and wall positions and velocities decode with three components", "[vtk][output][3d]") {
  Duct duct(true);
  auto sys = assemble_system<3>(duct_config("wall_particles"), duct.particles, duct.domain, duct.dx, &duct.walls);
  std::vector<double> y = sys->initial_state(), ydot(y.size());
  const auto& L = sys->layout();
  const auto& P = sys->particles();
  const std::size_t nf = P.n_fluid;
  y[L.position(0) + 3] += 0.6;  // one periodic length out of the box: written wrapped
  const double t = 0.25;        // the walls have moved 0.05 m along x
  sys->rhs(t, y.data(), ydot.data());
  const Part fl = decode(vtp_file<3>(*sys, y.data(), t, VtkPart::fluid));
  const Part wa = decode(vtp_file<3>(*sys, y.data(), t, VtkPart::walls));
  REQUIRE(fl.n == nf);
  REQUIRE(wa.n == P.size() - nf);
  REQUIRE(wa.n > 0);
  for (const Part* part : {&fl, &wa}) {
    const std::size_t first = part == &fl ? 0 : nf;
    for (std::size_t k = 0; k < part->n; ++k) {
      const std::size_t i = first + k;
      REQUIRE(part->point("id")[k] == static_cast<double>(i));
      for (int d = 0; d < 3; ++d) {
        const double x = i < nf ? y[L.position(d) + i] : P.wall_position(d, i, t);
        REQUIRE(part->xyz[3 * k + d] == sys->domain().wrap(d, x));
        REQUIRE(part->point("velocity")[3 * k + d] == (i < nf ? y[L.velocity(d) + i] : P.v[d][i]));
      }
      REQUIRE(part->point("density")[k] == sys->density()[i]);
      REQUIRE(part->point("kind")[k] == (i < nf ? 0.0 : 1.0));
    }
  }
  CHECK(fl.xyz[3 * 3] < 0.6);       // wrapped back
  CHECK(fl.xyz[3 * 3 + 2] == 0.05);  // the third coordinate is the particle's own z
  double zmin = 1.0, vz_abs = 0.0;
  for (std::size_t k = 0; k < wa.n; ++k) zmin = std::min(zmin, wa.xyz[3 * k + 2]);
  for (std::size_t k = 0; k < fl.n; ++k) vz_abs += std::abs(fl.point("velocity")[3 * k + 2]);
  CHECK(zmin == Approx(-0.25));  // the third wall layer below z = 0
  CHECK(vz_abs > 0.0);
}

TEST_CASE("vtk 3D: ghost images behind the duct's four walls", "[vtk][ghost][3d]") {
  Duct duct(false);
  auto sys = assemble_system<3>(duct_config("ghost"), duct.particles, duct.domain, duct.dx, &duct.walls);
  std::vector<double> y = sys->initial_state(), ydot(y.size());
  sys->rhs(0.0, y.data(), ydot.data());
  const std::size_t nb = sys->base_particles(), ng = sys->generated_particles();
  REQUIRE(ng > 0);
  const Part g = decode(vtp_file<3>(*sys, y.data(), 0.0, VtkPart::ghosts));
  REQUIRE(g.n == ng);
  std::size_t below = 0;
  for (std::size_t k = 0; k < ng; ++k) {
    REQUIRE(g.point("kind")[k] == 2.0);
    for (int d = 0; d < 3; ++d) {
      REQUIRE(g.xyz[3 * k + d] == sys->positions()[d][nb + k]);
      REQUIRE(g.point("velocity")[3 * k + d] == sys->velocities()[d][nb + k]);
    }
    const double yv = g.xyz[3 * k + 1], z = g.xyz[3 * k + 2];
    REQUIRE((yv < 0.0 || yv > 0.5 || z < 0.0 || z > 0.4));  // behind a wall
    below += z < 0.0;
  }
  CHECK(below > 0);
}
