// Wall treatments in 3D, at unit level: a tank of water at rest, hydrostatic, with wall particles from
// the geometry kit (box_container_walls<3>: floor and four sides, open top) held at rest density,
// with extrapolated pressures (Adami et al. 2012) or as dynamic boundary particles (Crespo et al.
// 2007), and the same tank with ghost walls (BoxWalls<3>, images up to the seven of a corner). The
// fluid next to the floor, the sides, their edges and corners must get the acceleration of the
// treatment. Also the repulsive force of a plane of virtual particles.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "sphmol/boundary/repulsive_force.hpp"
#include "sphmol/geometry/wall_layers.hpp"
#include "sphmol/physics/eos_tait.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/scenes/lattice_mass.hpp"

#include "workspace_pairs.hpp"

using namespace sphmol;

namespace {

constexpr double kG = 9.81, kRho0 = 1000.0;

// Fluid [0, Lx] x [0, Ly] x [0, H] on the cubic lattice of spacing dx = 0.02 m at hydrostatic density,
// and the walls around it.
struct Tank3 {
  double dx = 0.02, Lx = 0.2, Ly = 0.16, H = 0.2;
  double c0 = 10.0 * std::sqrt(kG * 0.2);  // 10 x the largest free-fall speed
  TaitLaw law{c0, kRho0, 7.0};
  Particles<3> particles;
  Domain<3> domain;
  BoxWalls<3> walls{};
  std::size_t n_fluid = 0;

  // wall_particles: walls made by box_container_walls<3> (thickness: the kernel support, 3 spacings);
  // their density is rho0 unless `hydrostatic_walls` (the fluid's hydrostatic law continued into them).
  // `closed`: a lid of wall particles too.
  Tank3(bool wall_particles, bool hydrostatic_walls, bool closed = false) {
    const double h = 1.3 * dx, m = lattice_particle_mass<3>("cubic_spline", kRho0, dx, h);
    const int nx = 10, ny = 8, nz = 10;
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          const double z = (k + 0.5) * dx;
          particles.add(Kind::Fluid, {(i + 0.5) * dx, (j + 0.5) * dx, z}, {0, 0, 0}, m, density_at(z));
        }
    n_fluid = particles.n_fluid;
    if (wall_particles) {
      geometry::Lattice<3> lat;
      lat.spacing = dx;
      for (const auto& p : geometry::box_container_walls<3>({0, 0, 0}, {Lx, Ly, H}, {false, false, false, false, false, !closed},
                                                            lat, 3 * dx))
        particles.add(Kind::Wall, p.x, {0, 0, 0}, m, hydrostatic_walls ? density_at(p.x[2]) : kRho0, p.normal, p.depth);
    }
    const double margin = 4 * dx;
    domain.lo = {-margin, -margin, -margin};
    domain.hi = {Lx + margin, Ly + margin, H + margin};
    walls[0][0] = {true, 0.0, true, {}};
    walls[0][1] = {true, Lx, true, {}};
    walls[1][0] = {true, 0.0, true, {}};
    walls[1][1] = {true, Ly, true, {}};
    walls[2][0] = {true, 0.0, true, {}};
  }
  double density_at(double z) const { return law.density(kRho0 * kG * (H - z)); }

  Config config(const std::string& boundary, const std::string& wall_pressure, bool gravity = true) const {
    Config c;
    c.case_name = "tank";
    c.dimension = 3;
    c.fluid.density = kRho0;
    c.fluid.kinematic_viscosity = 0.0;
    c.fluid.eos.type = "tait";
    c.fluid.eos.sound_speed = c0;
    c.fluid.body_force = {0.0, 0.0, gravity ? -kG : 0.0};
    c.discretization.density = "continuity";
    c.discretization.viscosity = "none";
    c.discretization.wall_model = "prescribed";
    c.discretization.boundary = boundary;
    c.discretization.wall_pressure = wall_pressure;
    c.discretization.neighbor_search = "cell_list";
    return c;
  }

  // Which walls fluid particle i is next to (within `rows` spacings): bit 2 d + side.
  unsigned near_walls(std::size_t i, int rows) const {
    const double lim = rows * dx;
    const double L[3] = {Lx, Ly, H};
    unsigned mask = 0;
    for (int d = 0; d < 3; ++d) {
      if (particles.x[d][i] < lim) mask |= 1u << (2 * d);
      if (d < 2 && L[d] - particles.x[d][i] < lim) mask |= 1u << (2 * d + 1);
    }
    return mask;
  }
};

struct Rates {
  std::unique_ptr<SphSystem<3>> sys;
  std::vector<double> y, ydot;
  double a(int d, std::size_t i) const { return ydot[sys->layout().velocity(d) + i]; }
};

Rates evaluate(const Tank3& tank, const Config& c) {
  Rates r;
  r.sys = assemble_system<3>(c, tank.particles, tank.domain, tank.dx, &tank.walls);
  r.y = r.sys->initial_state();
  r.ydot.assign(r.y.size(), 0.0);
  r.sys->rhs(0.0, r.y.data(), r.ydot.data());
  return r;
}

// Every fluid particle within two spacings of a wall and three below the free surface (whose
// missing half-support is not the walls' business): the largest |a| per direction, and how many
// particles of each kind of place (floor, side, edge, corner) were seen.
struct NearWall {
  double a_max[3] = {0, 0, 0};
  int floor = 0, side = 0, vertical_edge = 0, floor_edge = 0, corner = 0;
};

NearWall near_wall_accelerations(const Tank3& tank, const Rates& r) {
  NearWall out;
  for (std::size_t i = 0; i < tank.n_fluid; ++i) {
    const unsigned mask = tank.near_walls(i, 2);
    if (mask == 0 || tank.particles.x[2][i] > tank.H - 3 * tank.dx) continue;
    for (int d = 0; d < 3; ++d) out.a_max[d] = std::max(out.a_max[d], std::abs(r.a(d, i)));
    const bool on_floor = (mask & 0b010000u) != 0;
    const int sides = __builtin_popcount(mask & 0b1111u);
    if (on_floor && sides == 0) ++out.floor;
    if (!on_floor && sides == 1) ++out.side;
    if (!on_floor && sides == 2) ++out.vertical_edge;
    if (on_floor && sides == 1) ++out.floor_edge;
    if (on_floor && sides == 2) ++out.corner;
  }
  return out;
}

void check_balanced(const Tank3& tank, const Rates& r, double vertical, double horizontal) {
  const NearWall nw = near_wall_accelerations(tank, r);
  CHECK(nw.floor > 0);
  CHECK(nw.side > 0);
  CHECK(nw.vertical_edge > 0);
  CHECK(nw.floor_edge > 0);
  CHECK(nw.corner == 4 * 2 * 2 * 2);  // two rows each way at each of the four bottom corners
  CHECK(nw.a_max[2] < vertical * kG);
  CHECK(nw.a_max[0] < horizontal * kG);
  CHECK(nw.a_max[1] < horizontal * kG);
}

}  // namespace

TEST_CASE("3D closed box, wall particles at rest density: complete supports at faces, edges, corners", "[boundary][3d]") {
  // No gravity, and a lid: the fluid is at rho0 too. With summation density every fluid particle, at
  // the faces, their edges and the eight corners, must find rho0 (the walls fill its support) and no force.
  Tank3 tank(true, false, true);
  for (std::size_t i = 0; i < tank.n_fluid; ++i) tank.particles.rho[i] = kRho0;
  Config c = tank.config("wall_particles", "rest", false);
  c.discretization.density = "summation";
  const Rates r = evaluate(tank, c);
  const auto& rho = r.sys->density();
  for (std::size_t i = 0; i < tank.n_fluid; ++i) {
    REQUIRE(rho[i] == Approx(kRho0).epsilon(1e-12));
    for (int d = 0; d < 3; ++d) REQUIRE(std::abs(r.a(d, i)) < 1e-9 * kG);
  }
}

TEST_CASE("3D tank under gravity, wall particles at rest density: the walls pull the fluid in", "[boundary][3d]") {
  // Walls at rho0 have p = 0 beside a column whose pressure is rho0 g H at the bottom. In the symmetric
  // gradient each neighbour j pushes i away with m_j (p_i/rho_i^2 + p_j/rho_j^2) |grad W|: walls with
  // p_j = 0 push less than the fluid they stand for would, so the first rows are drawn into the floor
  // (several g, on top of gravity) and towards the side walls (the reason for the other treatments).
  const Tank3 tank(true, false);
  const Rates r = evaluate(tank, tank.config("wall_particles", "rest"));
  int floor = 0, side = 0;
  for (std::size_t i = 0; i < tank.n_fluid; ++i) {
    const unsigned mask = tank.near_walls(i, 1);
    if (mask == 0b010000u) {  // first row above the floor only
      ++floor;
      CHECK(r.a(2, i) < -3.0 * kG);
    }
    if (mask == 0b000001u && tank.particles.x[2][i] < tank.H - 3 * tank.dx) {  // first column at x = 0
      ++side;
      CHECK(r.a(0, i) < 0.0);
    }
  }
  CHECK(floor == 8 * 6);
  CHECK(side == 6 * 6);
}

TEST_CASE("3D tank under gravity, extrapolated wall pressure: balanced next to every wall", "[boundary][3d]") {
  const Tank3 tank(true, false);
  const Rates r = evaluate(tank, tank.config("wall_particles", "extrapolated"));
  check_balanced(tank, r, 0.05, 2e-3);  // measured: 0.035 g and 5e-4 g
  // The floor's pressure continues the hydrostatic law below z = 0.
  const auto& p = r.sys->pressure();
  int floor = 0;
  for (std::size_t i = tank.n_fluid; i < tank.particles.size(); ++i) {
    const double x = tank.particles.x[0][i], y = tank.particles.x[1][i], z = tank.particles.x[2][i];
    if (z > 0.0 || z < -2 * tank.dx || x < 3 * tank.dx || x > tank.Lx - 3 * tank.dx || y < 3 * tank.dx ||
        y > tank.Ly - 3 * tank.dx)
      continue;
    ++floor;
    CHECK(p[i] == Approx(kRho0 * kG * (tank.H - z)).epsilon(2e-2));
  }
  CHECK(floor == 4 * 2 * 2);
}

TEST_CASE("3D tank under gravity, dynamic boundary particles at hydrostatic density: balanced", "[boundary][3d]") {
  const Tank3 tank(true, true);
  const Rates r = evaluate(tank, tank.config("wall_particles", "dynamic"));
  // p depends on z alone and the wall lattice continues the fluid's: horizontal forces cancel exactly.
  check_balanced(tank, r, 0.05, 1e-9);
  // At rest the walls are neither compressed nor relieved.
  const auto& L = r.sys->layout();
  REQUIRE(L.n_wall_density == tank.particles.size() - tank.n_fluid);
  for (std::size_t k = 0; k < L.n_wall_density; ++k) REQUIRE(r.ydot[L.wall_density() + k] == 0.0);
}

TEST_CASE("3D tank under gravity, ghost walls: mirror images up to the corners, balanced", "[boundary][3d]") {
  const Tank3 tank(false, false);
  const Rates r = evaluate(tank, tank.config("ghost", "rest"));
  check_balanced(tank, r, 0.05, 1e-9);
  // Images: one per wall within the support (2h = 2.6 dx: three rows), one per pair of walls at the
  // edges and one through all three at the floor corners.
  std::size_t expected = 0;
  const int nx = 10, ny = 8, nz = 10, rows = 3;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int near_x = (i < rows) + (i >= nx - rows), near_y = (j < rows) + (j >= ny - rows), near_z = k < rows;
        expected += (1 + near_x) * (1 + near_y) * (1 + near_z) - 1;
      }
  CHECK(r.sys->generated_particles() == expected);
}

TEST_CASE("3D virtual repulsive wall: a plane of virtual particles pushes straight out of it", "[boundary][3d]") {
  // Virtual particles at dx/2 on the plane z = 0, a fluid particle at height 0.4 dx above a point
  // midway between four of them: the lateral pulls cancel, the normal push is the sum of eq 2.76.
  const double dx = 0.1, ds = 0.5 * dx, z0 = 0.4 * dx;
  const RepulsiveLaw law{1.0, 12.0, 4.0, dx};
  Particles<3> P;
  P.add(Kind::Fluid, {0.5 + 0.5 * ds, 0.5 + 0.5 * ds, z0}, {0, 0, 0}, 1.0, 1.0);
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i) P.add(Kind::Wall, {i * ds, j * ds, 0.0}, {0, 0, 0}, 0.0, 1.0);
  Domain<3> dom;
  dom.lo = {0.0, 0.0, -0.5};
  dom.hi = {1.0, 1.0, 0.5};
  Workspace<3> w;
  w.n = P.size();
  w.n_fluid = 1;
  w.particles = &P;
  w.domain = &dom;
  w.h = 0.5 * dx;
  for (int d = 0; d < 3; ++d) w.x[d] = P.x[d];
  PairList verlet;
  build_workspace_pairs<3, CubicSpline<3>>(w, P, dom, 2.0 * w.h, verlet);
  double a[3] = {0, 0, 0};
  w.dvdt = {&a[0], &a[1], &a[2]};
  RepulsiveBoundary<3>(law).apply(w);
  double expected = 0.0;
  int within = 0;
  for (std::size_t j = 1; j < P.size(); ++j) {
    const double rx = P.x[0][0] - P.x[0][j], ry = P.x[1][0] - P.x[1][j], r = std::sqrt(rx * rx + ry * ry + z0 * z0);
    expected += law.factor(r) * z0;
    within += r <= law.r0;
  }
  REQUIRE(within >= 4);
  CHECK(a[2] == Approx(expected).epsilon(1e-12));
  CHECK(a[2] > 0.0);
  CHECK(std::abs(a[0]) < 1e-12 * a[2]);
  CHECK(std::abs(a[1]) < 1e-12 * a[2]);
}
