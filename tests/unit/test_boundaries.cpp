// Tait EOS (Niedoba 2012, eq 2.75), the repulsive boundary force (Niedoba 2012, eq 2.76) and the ghost generator
// (Niedoba 2012, §2.2.4, §3.3, Fig 3.4): values, signs, mirror positions/velocities, corner images, counts,
// the copied energy and h, and the hydrostatic image pressure.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "sphmol/boundary/ghost_hydrostatic_pressure.hpp"
#include "sphmol/boundary/ghost_particles.hpp"
#include "sphmol/boundary/repulsive_force.hpp"
#include "sphmol/physics/eos_tait.hpp"

using namespace sphmol;

TEST_CASE("Tait EOS: zero at rest density, slope c0^2, inverse, clamp", "[tait]") {
  const double c0 = 29.7, rho0 = 1000.0;
  const TaitLaw law(c0, rho0, 7.0);
  CHECK(law.B == Approx(c0 * c0 * rho0 / 7.0));
  CHECK(law.pressure(rho0) == 0.0);
  const double d = 1e-6 * rho0;
  CHECK((law.pressure(rho0 + d) - law.pressure(rho0 - d)) / (2 * d) == Approx(c0 * c0).epsilon(1e-8));
  CHECK(law.pressure(1.01 * rho0) == Approx(law.B * (std::pow(1.01, 7.0) - 1.0)));
  for (double p : {-5e4, 0.0, 1e3, 2e5}) CHECK(law.pressure(law.density(p)) == Approx(p).margin(1e-6));
  Workspace<2> w;
  w.n = 2;
  w.rho = {0.99 * rho0, 1.01 * rho0};
  w.p = {0.0, 0.0};
  w.c = {0.0, 0.0};  // the EOS also sets the sound speed
  TaitEos<2>(c0, rho0, 7.0).apply(w);
  CHECK(w.p[0] < 0.0);
  CHECK(w.p[1] > 0.0);
  TaitEos<2>(c0, rho0, 7.0, true).apply(w);
  CHECK(w.p[0] == 0.0);
  CHECK(w.p[1] == Approx(law.pressure(1.01 * rho0)));
}

TEST_CASE("repulsive force of Niedoba 2012, eq 2.76", "[repulsive]") {
  const RepulsiveLaw law{2.0, 12.0, 4.0, 0.1};
  CHECK(law.factor(0.1) == Approx(0.0).margin(1e-12));  // (r0/r)^p1 - (r0/r)^p2 = 0 at r = r0
  CHECK(law.factor(0.1001) == 0.0);                      // outside r0
  const double r = 0.05, q = 2.0;
  CHECK(law.factor(r) == Approx(2.0 * (std::pow(q, 12) - std::pow(q, 4)) / (r * r)));
  CHECK(law.factor(r) > 0.0);  // pushes i away from j: a = factor * x_ij

  // As a term: a fluid particle above a wall particle is pushed up, and only by the wall.
  Particles<2> pt;
  pt.add(Kind::Fluid, {0.0, 0.05}, {0, 0}, 1.0, 1.0);
  pt.add(Kind::Fluid, {0.04, 0.05}, {0, 0}, 1.0, 1.0);
  pt.add(Kind::Wall, {0.0, 0.0}, {0, 0}, 0.0, 1.0);
  Workspace<2> w;
  w.n = 3;
  w.n_fluid = 2;
  w.particles = &pt;
  w.pairs.offset = {0, 2, 3, 4};
  w.pairs.j = {1, 2, 0, 0};
  w.dx[0] = {-0.04, 0.0, 0.04, 0.0};
  w.dx[1] = {0.0, 0.05, 0.0, -0.05};
  double ax[2] = {0, 0}, ay[2] = {0, 0};
  w.dvdt = {ax, ay};
  RepulsiveBoundary<2>(law).apply(w);
  CHECK(ax[0] == 0.0);
  CHECK(ay[0] == Approx(law.factor(0.05) * 0.05));
  CHECK(ax[1] == 0.0);
  CHECK(ay[1] == 0.0);  // its only pair is fluid-fluid
}

namespace {
// The workspace of particles `pt` at h = 1, before any term ran: positions, velocities, densities.
template <int D>
Workspace<D> workspace_of(const Particles<D>& pt) {
  Workspace<D> w;
  w.n = pt.size();
  w.n_fluid = pt.n_fluid;
  for (int d = 0; d < D; ++d) w.x[d] = pt.x[d], w.v[d] = pt.v[d];
  w.rho = pt.rho;
  w.p.assign(w.n, 0.0);
  w.h = 1.0;
  w.hs.assign(w.n, 1.0);
  w.e.assign(w.n, 0.0);
  return w;
}

// Unit box with walls on the left (moving up at 0.3), bottom (moving right at 1) and right; top open.
GhostGenerator<2> make_generator(bool no_slip) {
  BoxWalls<2> walls{};
  walls[0][0] = {true, 0.0, no_slip, {0.0, 0.3}};
  walls[0][1] = {true, 1.0, no_slip, {0.0, 0.0}};
  walls[1][0] = {true, 0.0, no_slip, {1.0, 0.0}};
  return GhostGenerator<2>(walls, 0.1);
}
struct Scene {
  Particles<2> pt;
  Workspace<2> w;
  Scene() {
    pt.add(Kind::Fluid, {0.05, 0.03}, {0.2, -0.4}, 2.0, 1000.0);  // bottom-left corner: 3 images
    pt.add(Kind::Fluid, {0.5, 0.02}, {0.1, 0.5}, 3.0, 1001.0);    // bottom only: 1 image
    pt.add(Kind::Fluid, {0.5, 0.5}, {0.0, 0.0}, 1.0, 1000.0);     // interior: none
    pt.add(Kind::Fluid, {0.97, 0.95}, {0.0, 0.1}, 1.0, 1000.0);   // right wall near the open top: 1
    pt.add(Kind::Wall, {0.5, -0.5}, {0.0, 0.0}, 1.0, 1000.0);     // a scene wall particle (base)
    w = workspace_of(pt);  // h = 1 with support 0.1 (make_generator): images within 0.1 of a wall
  }
};
}  // namespace

TEST_CASE("ghost generator: mirror positions, no-slip velocities, corner images, counts", "[ghost]") {
  auto gen = make_generator(true);
  Scene s;
  const std::size_t base = s.w.n;
  CHECK(gen.generate(base, s.pt, s.w));  // first call: a new set
  REQUIRE(gen.count() == 5);
  REQUIRE(s.w.n == base + 5);
  REQUIRE(s.pt.size() == base + 5);
  const auto& src = gen.sources();
  const auto& mask = gen.masks();
  int corner = 0;
  for (std::size_t g = 0; g < gen.count(); ++g) {
    const std::size_t k = base + g, i = src[g];
    CHECK(s.pt.kind[k] == Kind::Wall);
    CHECK(s.pt.mass[k] == s.pt.mass[i]);  // Niedoba 2012, §3.3: m_f = m
    if (i == 0 && mask[g] == 0b0101) {    // mirrored through left and bottom walls: the corner image
      ++corner;
      CHECK(s.w.x[0][k] == Approx(-0.05));
      CHECK(s.w.x[1][k] == Approx(-0.03));
      // Each component is normal to one of the walls and mirrored about that wall's normal velocity
      // (0): the bottom's belt speed runs into the left wall and the left's into the bottom, so
      // neither enters (with -v + v_left + v_bottom the pair moved through the walls on average).
      CHECK(s.w.v_viscous[0][k] == Approx(-0.2));
      CHECK(s.w.v_viscous[1][k] == Approx(0.4));
      CHECK(s.w.v[0][k] == Approx(-0.2));  // free slip through both: the same here
      CHECK(s.w.v[1][k] == Approx(0.4));
    }
    if (i == 1) {  // bottom image: 2 v_w - v for the viscous terms, free slip for the rest
      CHECK(s.w.x[0][k] == Approx(0.5));
      CHECK(s.w.x[1][k] == Approx(-0.02));
      CHECK(s.w.v_viscous[0][k] == Approx(2.0 - 0.1));
      CHECK(s.w.v_viscous[1][k] == Approx(-0.5));
      CHECK(s.w.v[0][k] == Approx(0.1));
      CHECK(s.w.v[1][k] == Approx(-0.5));
    }
    if (i == 3) {  // right wall image, no image through the open top
      CHECK(mask[g] == 0b0010);
      CHECK(s.w.x[0][k] == Approx(1.03));
      CHECK(s.w.x[1][k] == Approx(0.95));
      CHECK(s.w.v_viscous[1][k] == Approx(-0.1));
      CHECK(s.w.v[1][k] == Approx(0.1));
    }
    CHECK(i != 2);
  }
  CHECK(corner == 1);
  // The viscous velocities of the fluid and of the scene's wall particle are their own.
  REQUIRE(s.w.v_viscous[0].size() == s.w.n);
  for (std::size_t i = 0; i < base; ++i)
    for (int d = 0; d < 2; ++d) CHECK(s.w.v_viscous[d][i] == s.w.v[d][i]);
  // Same configuration again: same set, no rebuild needed; a particle leaving the band changes it.
  CHECK_FALSE(gen.generate(base, s.pt, s.w));
  s.w.x[1][1] = 0.3;
  CHECK(gen.generate(base, s.pt, s.w));
  CHECK(gen.count() == 4);
  CHECK(s.w.n == base + 4);

  // Density copy: ghosts take their source's density.
  s.w.rho[0] = 1234.0;
  GhostStateCopy<2>(&gen).apply(s.w);
  for (std::size_t g = 0; g < gen.count(); ++g) CHECK(s.w.rho[base + g] == s.w.rho[gen.sources()[g]]);
}

TEST_CASE("ghost generator: free slip mirrors only the normal component (Niedoba 2012, eqs 2.77-2.78)", "[ghost]") {
  auto gen = make_generator(false);
  Scene s;
  const std::size_t base = s.w.n;
  gen.generate(base, s.pt, s.w);
  CHECK(s.w.v_viscous[0].empty());  // no no-slip mirror: the viscous terms read w.v
  for (std::size_t g = 0; g < gen.count(); ++g) {
    const std::size_t k = base + g, i = gen.sources()[g];
    if (i == 1) {  // bottom wall: tangential kept, normal mirrored about v_w,n = 0
      CHECK(s.w.v[0][k] == Approx(0.1));
      CHECK(s.w.v[1][k] == Approx(-0.5));
    }
    if (i == 0 && gen.masks()[g] == 0b0101) {  // corner: both components mirrored
      CHECK(s.w.v[0][k] == Approx(-0.2));
      CHECK(s.w.v[1][k] == Approx(0.4));
    }
    if (i == 0 && gen.masks()[g] == 0b0001) {  // left wall (moving tangentially): tangential kept
      CHECK(s.w.x[0][k] == Approx(-0.05));
      CHECK(s.w.v[0][k] == Approx(-0.2));
      CHECK(s.w.v[1][k] == Approx(-0.4));
    }
  }
}

TEST_CASE("ghost generator: images take the source's energy and h, the band follows the largest h", "[ghost]") {
  auto gen = make_generator(false);
  Scene s;
  const std::size_t base = s.w.n;
  s.w.e = {2.5, 1.8, 1.0, 1.0, 0.7};
  s.w.hs = {1.0, 1.2, 1.0, 1.0, 1.0};
  gen.generate(base, s.pt, s.w);
  REQUIRE(s.w.e.size() == s.w.n);
  REQUIRE(s.w.hs.size() == s.w.n);
  REQUIRE(s.w.c.size() == s.w.n);
  for (std::size_t g = 0; g < gen.count(); ++g) {
    CHECK(s.w.e[base + g] == s.w.e[gen.sources()[g]]);
    CHECK(s.w.hs[base + g] == s.w.hs[gen.sources()[g]]);
  }
  // Band = support x max h = 0.1 x 1.2 = 0.12: a particle 0.11 above the bottom wall has an image.
  s.w.x[1][2] = 0.11;
  s.w.x[0][2] = 0.5;
  gen.generate(base, s.pt, s.w);
  CHECK(std::count(gen.sources().begin(), gen.sources().end(), 2u) == 1);
  s.w.hs = {1.0, 1.0, 1.0, 1.0, 1.0};  // band 0.1: no longer
  gen.generate(base, s.pt, s.w);
  CHECK(std::count(gen.sources().begin(), gen.sources().end(), 2u) == 0);
}

TEST_CASE("ghost hydrostatic pressure: images below carry p_i + rho_i g 2d, side images p_i", "[ghost]") {
  auto gen = make_generator(false);
  Scene s;
  const std::size_t base = s.w.n;
  gen.generate(base, s.pt, s.w);
  const TaitLaw law(20.0, 1000.0, 7.0);
  GhostStateCopy<2>(&gen).apply(s.w);
  for (std::size_t i = 0; i < s.w.n; ++i) s.w.p[i] = law.pressure(s.w.rho[i]);  // the EOS pass
  const std::array<double, 2> g{0.0, -9.81};
  GhostHydrostaticPressure<2> term(&gen, g, 0.0, [law](double p) { return law.density(p); });
  term.apply(s.w);
  for (std::size_t k = 0; k < gen.count(); ++k) {
    const std::size_t i = gen.sources()[k], gi = base + k;
    const double dy = s.w.x[1][gi] - s.w.x[1][i];  // -2d below the bottom wall, 0 beside a side wall
    CHECK(s.w.p[gi] == Approx(s.w.p[i] + s.w.rho[i] * 9.81 * (-dy)));
    CHECK(law.pressure(s.w.rho[gi]) == Approx(s.w.p[gi]));  // density consistent with the EOS
    if (gen.masks()[k] == 0b0010) CHECK(s.w.p[gi] == s.w.p[i]);  // right wall: no jump
    if (i == 1) CHECK(s.w.p[gi] == Approx(s.w.p[1] + s.w.rho[1] * 9.81 * 0.04));
  }
  // Ramped gravity: at t = 0 of a ramp the images are plain copies.
  GhostStateCopy<2>(&gen).apply(s.w);
  for (std::size_t i = 0; i < s.w.n; ++i) s.w.p[i] = law.pressure(s.w.rho[i]);
  s.w.t = 0.0;
  GhostHydrostaticPressure<2>(&gen, g, 1.0, [law](double p) { return law.density(p); }).apply(s.w);
  for (std::size_t k = 0; k < gen.count(); ++k) CHECK(s.w.p[base + k] == Approx(s.w.p[gen.sources()[k]]));
}

TEST_CASE("ghost generator: oblique mirror planes, their corners and the box faces as planes", "[ghost]") {
  // A floor tilted by 30 degrees through the origin (fluid above it), a side wall at right angles to
  // it through (0.2, 0) along the floor, moving along itself, and a third plane at 60 degrees to the
  // floor far away (no corner images with it).
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  GhostPlane<2> floor{{-s, c}, 0.0, true, {0.3 * c, 0.3 * s}};   // a belt along the floor
  GhostPlane<2> side{{-c, -s}, -(c * 0.2 * c + s * 0.2 * s), true, {0.0, 0.0}};
  GhostPlane<2> far{{0.0, 1.0}, -5.0, false, {0.0, 0.0}};       // y = -5 (never near)
  GhostGenerator<2> gen(BoxWalls<2>{}, 0.1, {floor, side, far});
  Particles<2> pt;
  // At distance 0.03 from the floor, 0.05 along it from the origin: one image; at 0.02 from the floor
  // and 0.04 from the side wall: two images and their corner image.
  const auto at = [&](double along, double up) { return std::array<double, 2>{along * c - up * s, along * s + up * c}; };
  pt.add(Kind::Fluid, at(0.05, 0.03), {0.1, -0.2}, 1.0, 1000.0);
  pt.add(Kind::Fluid, at(0.16, 0.02), {0.4, 0.1}, 1.0, 1000.0);
  Workspace<2> w = workspace_of(pt);
  gen.generate(w.n, pt, w);
  REQUIRE(gen.count() == 4);
  const std::size_t base = 2;
  const auto rel = [&](std::size_t g) {  // the image in the floor's frame: (along, up)
    return std::array<double, 2>{w.x[0][base + g] * c + w.x[1][base + g] * s, -w.x[0][base + g] * s + w.x[1][base + g] * c};
  };
  int floor_images = 0, side_images = 0, corners = 0;
  for (std::size_t g = 0; g < gen.count(); ++g) {
    const auto q = rel(g);
    const std::size_t i = gen.sources()[g];
    const double vx = w.v_viscous[0][base + g], vy = w.v_viscous[1][base + g];
    if (gen.masks()[g] == 0b001) {  // the floor: up -> -up; no slip: 2 v_w - v
      ++floor_images;
      CHECK(q[0] == Approx(i == 0 ? 0.05 : 0.16));
      CHECK(q[1] == Approx(i == 0 ? -0.03 : -0.02));
      CHECK(vx == Approx(2 * 0.3 * c - pt.v[0][i]));
      CHECK(vy == Approx(2 * 0.3 * s - pt.v[1][i]));
    } else if (gen.masks()[g] == 0b010) {  // the side wall at along = 0.2
      ++side_images;
      CHECK(q[0] == Approx(0.24));
      CHECK(q[1] == Approx(0.02));
      CHECK(vx == Approx(-0.4));
      CHECK(vy == Approx(-0.1));
    } else {  // the corner: through both; the floor's belt runs along the side wall's normal: -v
      ++corners;
      CHECK(gen.masks()[g] == 0b011);
      CHECK(q[0] == Approx(0.24));
      CHECK(q[1] == Approx(-0.02));
      CHECK(vx == Approx(-0.4));
      CHECK(vy == Approx(-0.1));
    }
  }
  CHECK(floor_images == 2);
  CHECK(side_images == 1);
  CHECK(corners == 1);
  CHECK(gen.max_wall_speed() == Approx(0.3));

  // Free slip on an oblique plane: the normal component of v - v_w mirrored, the tangential kept.
  GhostPlane<2> slip = floor;
  slip.no_slip = false;
  GhostGenerator<2> free(BoxWalls<2>{}, 0.1, {slip});
  Particles<2> p1 = pt;
  Workspace<2> w1 = w;
  w1.n = 2;
  free.generate(2, p1, w1);
  for (std::size_t g = 0; g < free.count(); ++g) {
    const std::size_t i = free.sources()[g];
    const double vt = w1.v[0][2 + g] * c + w1.v[1][2 + g] * s, vn = -w1.v[0][2 + g] * s + w1.v[1][2 + g] * c;
    CHECK(vt == Approx(pt.v[0][i] * c + pt.v[1][i] * s));
    CHECK(vn == Approx(-(-pt.v[0][i] * s + pt.v[1][i] * c)));
  }

  // The box's faces given as planes make the same images as the box walls.
  auto box = make_generator(true);
  BoxWalls<2> none{};
  std::vector<GhostPlane<2>> faces{{{1.0, 0.0}, 0.0, true, {0.0, 0.3}}, {{-1.0, 0.0}, -1.0, true, {0.0, 0.0}},
                                   {{0.0, 1.0}, 0.0, true, {1.0, 0.0}}};
  GhostGenerator<2> as_planes(none, 0.1, faces);
  Scene a, b;
  box.generate(a.w.n, a.pt, a.w);
  as_planes.generate(b.w.n, b.pt, b.w);
  REQUIRE(as_planes.count() == box.count());
  CHECK(as_planes.masks() == box.masks());
  for (std::size_t k = 0; k < a.w.n; ++k)
    for (int d = 0; d < 2; ++d) {
      CHECK(b.w.x[d][k] == Approx(a.w.x[d][k]).margin(1e-15));
      CHECK(b.w.v[d][k] == Approx(a.w.v[d][k]).margin(1e-15));
      CHECK(b.w.v_viscous[d][k] == Approx(a.w.v_viscous[d][k]).margin(1e-15));
    }
}

TEST_CASE("ghost generator in 3D: an oblique plane and a box face at right angles to it", "[ghost][3d]") {
  // A floor tilted about y through the origin (normal n) and the box's lower y face at y = 0.
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  BoxWalls<3> box{};
  box[1][0] = {true, 0.0, true, {0.0, 0.0, 0.0}};
  GhostGenerator<3> gen(box, 0.1, {GhostPlane<3>{{-s, 0.0, c}, 0.0, true, {0.0, 0.0, 0.0}}});
  Particles<3> pt;
  // 0.04 above the floor, 0.03 from the y face, 0.2 along the floor.
  pt.add(Kind::Fluid, {0.2 * c - 0.04 * s, 0.03, 0.2 * s + 0.04 * c}, {0.1, 0.2, 0.3}, 1.0, 1000.0);
  Workspace<3> w = workspace_of(pt);
  gen.generate(1, pt, w);
  REQUIRE(gen.count() == 3);  // the y face, the floor, and the corner through both
  for (std::size_t g = 0; g < 3; ++g) {
    const std::size_t k = 1 + g;
    const double up = -s * w.x[0][k] + c * w.x[2][k], along = c * w.x[0][k] + s * w.x[2][k];
    CHECK(along == Approx(0.2));
    const std::uint32_t m = gen.masks()[g];
    CHECK(up == Approx(m & 0b10u ? -0.04 : 0.04));       // bit 1: the floor (after the box face)
    CHECK(w.x[1][k] == Approx(m & 0b01u ? -0.03 : 0.03));  // bit 0: the y face
    for (int d = 0; d < 3; ++d) CHECK(w.v_viscous[d][k] == Approx(-pt.v[d][0]));  // no slip at rest: -v
  }
}

TEST_CASE("ghost generator: no-slip corner images keep every wall impermeable, the edge takes the walls' mean", "[ghost][3d]") {
  // A 3D lid z = 1 moving along x at U and the side wall y = 0 at rest: the edge between them runs
  // along x, the lid's motion is tangent to both, so the edge image's x velocity is 2 (U + 0)/2 - u;
  // y and z, each one wall's normal, are mirrored: the source-image pair crosses neither wall.
  const double U = 1.5;
  BoxWalls<3> box{};
  box[1][0] = {true, 0.0, true, {0.0, 0.0, 0.0}};
  box[2][1] = {true, 1.0, true, {U, 0.0, 0.0}};
  GhostGenerator<3> gen(box, 0.1);
  Particles<3> pt;
  pt.add(Kind::Fluid, {0.5, 0.03, 0.98}, {0.7, 0.2, -0.1}, 1.0, 1000.0);
  Workspace<3> w = workspace_of(pt);
  gen.generate(1, pt, w);
  REQUIRE(gen.count() == 3);
  for (std::size_t g = 0; g < 3; ++g) {
    const std::size_t k = 1 + g;
    if (gen.masks()[g] != 0b11u) continue;
    CHECK(w.x[1][k] == Approx(-0.03));
    CHECK(w.x[2][k] == Approx(1.02));
    CHECK(w.v_viscous[0][k] == Approx(U - 0.7));
    CHECK(w.v_viscous[1][k] == Approx(-0.2));
    CHECK(w.v_viscous[2][k] == Approx(0.1));
    CHECK(w.v[0][k] == Approx(0.7));  // free slip: the edge's tangent kept
    CHECK(w.v[1][k] == Approx(-0.2));
    CHECK(w.v[2][k] == Approx(0.1));
  }
  // In 2D the lid's corner with a side wall has no common tangent: the image is -v, and the mean of
  // source and image is at rest in both directions (the lid speed is the side wall's normal).
  BoxWalls<2> cav{};
  cav[0][1] = {true, 1.0, true, {0.0, 0.0}};
  cav[1][1] = {true, 1.0, true, {U, 0.0}};
  GhostGenerator<2> g2(cav, 0.1);
  Particles<2> p2;
  p2.add(Kind::Fluid, {0.97, 0.98}, {0.6, -0.3}, 1.0, 1000.0);
  Workspace<2> w2 = workspace_of(p2);
  g2.generate(1, p2, w2);
  REQUIRE(g2.count() == 3);
  for (std::size_t g = 0; g < 3; ++g) {
    const std::size_t k = 1 + g;
    if (g2.masks()[g] == 0b11u) {
      CHECK(w2.v_viscous[0][k] == Approx(-0.6));
      CHECK(w2.v_viscous[1][k] == Approx(0.3));
    } else if (g2.masks()[g] == 0b10u) {  // the lid alone: 2 U - u along it, -v across
      CHECK(w2.v_viscous[0][k] == Approx(2.0 * U - 0.6));
      CHECK(w2.v_viscous[1][k] == Approx(0.3));
      CHECK(w2.v[0][k] == Approx(0.6));  // free slip for every other term: the lid's normal mirrored only
      CHECK(w2.v[1][k] == Approx(0.3));
    }
  }
}
