// Particle shifting (physics/particle_shifting.hpp) on small 2D particle sets: no shift on a perfect
// lattice, a shift back towards the lattice sites on a jittered one (linear in A U), the Taylor
// correction (du . grad) v and (du . grad) rho for linear fields, and nothing with correction off.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "sphmol/kernels/wendland_c2.hpp"
#include "sphmol/physics/particle_shifting.hpp"
#include "sphmol/physics/summation_density.hpp"
#include "sphmol/scenes/lattice_mass.hpp"

#include "workspace_pairs.hpp"

using namespace sphmol;

namespace {

using K = WendlandC2Kernel<2>;

// n x n fluid lattice in [0, 1)^2, periodic or open, optionally jittered; h = 2 dx as the Taylor-Green case.
struct Lattice {
  Particles<2> P;
  Domain<2> dom;
  Workspace<2> w;
  PairList verlet;
  std::array<std::vector<double>, 2> dxdt, dvdt;
  std::vector<double> drhodt;
  double dx = 0.0, h = 0.0, rho0 = 1.0;

  Lattice(int n, bool periodic, double jitter, unsigned seed = 11) {
    dx = 1.0 / n;
    h = 2.0 * dx;
    const double m = lattice_particle_mass<2>("wendland_c2", rho0, dx, h);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-jitter * dx, jitter * dx);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) P.add(Kind::Fluid, {(i + 0.5) * dx + u(rng), (j + 0.5) * dx + u(rng)}, {0, 0}, m, rho0);
    dom.lo = {0.0, 0.0};
    dom.hi = {1.0, 1.0};
    dom.periodic = {periodic, periodic};
    load_workspace(w, P, dom, h);
    w.W0 = K::W(0.0, h);
    build_workspace_pairs<2, K>(w, P, dom, K::support * h * 1.2, verlet);
    SummationDensity<2>().apply(w);
    clear();
  }
  void clear() {
    for (int d = 0; d < 2; ++d) {
      dxdt[d].assign(P.n_fluid, 0.0);
      dvdt[d].assign(P.n_fluid, 0.0);
      w.dxdt[d] = dxdt[d].data();
      w.dvdt[d] = dvdt[d].data();
    }
    drhodt.assign(P.n_fluid, 0.0);
    w.drhodt = drhodt.data();
  }
  void shift(double A, double U, bool correction) {
    ParticleShifting<2>(A, U, h, K::W(dx, h), correction).apply(w);
  }
  // Fluid particle nearest (x, y).
  std::size_t nearest(double x, double y) const {
    std::size_t best = 0;
    double bd = 1e9;
    for (std::size_t i = 0; i < P.n_fluid; ++i) {
      const double d = std::hypot(P.x[0][i] - x, P.x[1][i] - y);
      if (d < bd) bd = d, best = i;
    }
    return best;
  }
};

}  // namespace

TEST_CASE("particle shifting: nothing on a perfect periodic lattice", "[rhs][particle_shifting]") {
  Lattice f(16, true, 0.0);
  for (std::size_t i = 0; i < f.w.n; ++i) f.w.v[0][i] = std::sin(2 * M_PI * f.w.x[1][i]);
  f.shift(4.0, 1.0, true);
  for (std::size_t i = 0; i < f.P.n_fluid; ++i)
    for (int d = 0; d < 2; ++d) {
      CHECK(std::abs(f.dxdt[d][i]) < 1e-12);
      CHECK(std::abs(f.dvdt[d][i]) < 1e-10);
    }
}

TEST_CASE("particle shifting: jittered lattice is pushed back towards its sites, du linear in A U",
          "[rhs][particle_shifting]") {
  Lattice f(16, true, 0.15);
  f.shift(4.0, 1.0, false);
  double along = 0.0, norm = 0.0, disp = 0.0;
  for (std::size_t i = 0; i < f.P.n_fluid; ++i) {
    const int ix = static_cast<int>(i % 16), iy = static_cast<int>(i / 16);
    const double xi[2] = {f.P.x[0][i] - (ix + 0.5) * f.dx, f.P.x[1][i] - (iy + 0.5) * f.dx};
    for (int d = 0; d < 2; ++d) {
      along += f.dxdt[d][i] * xi[d];
      norm += f.dxdt[d][i] * f.dxdt[d][i];
      disp += xi[d] * xi[d];
    }
  }
  REQUIRE(norm > 0);
  // Back towards the sites, and clearly so: the cosine between shift and displacement is well below 0.
  CHECK(along / std::sqrt(norm * disp) < -0.3);
  const double first = f.dxdt[0][37], second = f.dxdt[1][101];
  f.clear();
  f.shift(2.0, 3.0, false);
  CHECK(f.dxdt[0][37] == Approx(1.5 * first).epsilon(1e-12));
  CHECK(f.dxdt[1][101] == Approx(1.5 * second).epsilon(1e-12));
}

TEST_CASE("particle shifting: the Taylor correction is (du . grad) v and (du . grad) rho for linear fields",
          "[rhs][particle_shifting]") {
  // One particle displaced from the middle of an open lattice, the others on their sites: the shift
  // pushes it back, and its values are corrected along the shift with the SPH gradient of v and rho.
  Lattice f(20, false, 0.0);
  const std::size_t c = f.nearest(0.5, 0.5);
  f.P.x[0][c] += 0.2 * f.dx;
  f.P.x[1][c] += 0.1 * f.dx;
  for (int d = 0; d < 2; ++d) f.w.x[d] = f.P.x[d];
  const double a = 0.7, b = -0.3, g = 0.02;  // v = (a y, b x), rho = rho0 (1 + g y) in the sums
  for (std::size_t i = 0; i < f.w.n; ++i) {
    f.w.v[0][i] = a * f.w.x[1][i];
    f.w.v[1][i] = b * f.w.x[0][i];
  }
  build_workspace_pairs<2, K>(f.w, f.P, f.dom, K::support * f.h * 1.2, f.verlet);
  SummationDensity<2>().apply(f.w);
  for (std::size_t i = 0; i < f.w.n; ++i) f.w.rho[i] = f.rho0 * (1.0 + g * f.w.x[1][i]);
  f.clear();
  f.shift(4.0, 1.0, true);
  const double du[2] = {f.dxdt[0][c], f.dxdt[1][c]};
  REQUIRE(du[0] < 0.0);  // pushed back along -x, the larger displacement
  // The SPH gradient on this nearly regular set is within a few per cent of the exact one.
  CHECK(f.dvdt[0][c] == Approx(a * du[1]).epsilon(0.05));
  CHECK(f.dvdt[1][c] == Approx(b * du[0]).epsilon(0.05));
  CHECK(f.drhodt[c] == Approx(f.rho0 * g * du[1]).epsilon(0.05));
  f.clear();
  f.shift(4.0, 1.0, false);
  CHECK(f.dvdt[0][c] == 0.0);
  CHECK(f.dvdt[1][c] == 0.0);
  CHECK(f.drhodt[c] == 0.0);
}
