// Tait EOS (seed 003 eq 2.75), the repulsive boundary force (003 eq 2.76) and the ghost generator
// (003 §2.2.4, §3.3, Fig 3.4): values, signs, mirror positions/velocities, corner images, counts.
#include <catch2/catch.hpp>

#include <cmath>

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

TEST_CASE("repulsive force of seed 003 eq 2.76", "[repulsive]") {
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
    w.n = pt.size();
    w.n_fluid = pt.n_fluid;
    for (int d = 0; d < 2; ++d) {
      w.x[d] = pt.x[d];
      w.v[d] = pt.v[d];
    }
    w.rho = pt.rho;
    w.p.assign(w.n, 0.0);
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
    CHECK(s.pt.mass[k] == s.pt.mass[i]);  // 003 §3.3: m_f = m
    if (i == 0 && mask[g] == 0b0101) {    // mirrored through left and bottom walls: the corner image
      ++corner;
      CHECK(s.w.x[0][k] == Approx(-0.05));
      CHECK(s.w.x[1][k] == Approx(-0.03));
      // -v + v_left + v_bottom
      CHECK(s.w.v[0][k] == Approx(-0.2 + 0.0 + 1.0));
      CHECK(s.w.v[1][k] == Approx(0.4 + 0.3 + 0.0));
    }
    if (i == 1) {  // bottom image: 2 v_w - v
      CHECK(s.w.x[0][k] == Approx(0.5));
      CHECK(s.w.x[1][k] == Approx(-0.02));
      CHECK(s.w.v[0][k] == Approx(2.0 - 0.1));
      CHECK(s.w.v[1][k] == Approx(-0.5));
    }
    if (i == 3) {  // right wall image, no image through the open top
      CHECK(mask[g] == 0b0010);
      CHECK(s.w.x[0][k] == Approx(1.03));
      CHECK(s.w.x[1][k] == Approx(0.95));
      CHECK(s.w.v[1][k] == Approx(-0.1));
    }
    CHECK(i != 2);
  }
  CHECK(corner == 1);
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

TEST_CASE("ghost generator: free slip mirrors only the normal component (003 eqs 2.77-2.78)", "[ghost]") {
  auto gen = make_generator(false);
  Scene s;
  const std::size_t base = s.w.n;
  gen.generate(base, s.pt, s.w);
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
