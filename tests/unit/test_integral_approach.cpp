// The integral approach's gas dynamics (physics/integral_approach_matrix.hpp and its pair terms):
// linear exactness on a distorted lattice, conservation of momentum and energy pair by pair, the
// standard form on a regular lattice, and the matrix at ghost images.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <random>

#include "sphmol/boundary/ghost_integral_approach_matrix.hpp"
#include "sphmol/kernels/registry.hpp"
#include "sphmol/kernels/truncated_exponential.hpp"
#include "sphmol/physics/artificial_conductivity_ia.hpp"
#include "sphmol/physics/artificial_viscosity_ia.hpp"
#include "sphmol/physics/continuity_density.hpp"
#include "sphmol/physics/continuity_density_ia.hpp"
#include "sphmol/physics/energy_equation_ia.hpp"
#include "sphmol/physics/integral_approach_matrix.hpp"
#include "sphmol/physics/pressure_gradient.hpp"
#include "sphmol/physics/pressure_gradient_ia.hpp"

#include "pair_term_fixture.hpp"
#include "workspace_pairs.hpp"

using namespace sphmol;

namespace {

// A square lattice of n x n at spacing dx, each particle moved by up to `jitter` spacings in each
// direction, masses and densities varied by `spread` (so the volumes m / rho differ), open domain.
void distorted_lattice(PairTermFixture<2>& f, int n, double dx, double jitter, double spread, unsigned seed,
                       bool variable_h = false) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  f.domain.lo = {-10.0, -10.0};
  f.domain.hi = {10.0, 10.0};
  f.domain.periodic = {false, false};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      f.P.add(Kind::Fluid, {(i + jitter * U(gen)) * dx, (j + jitter * U(gen)) * dx}, {U(gen), U(gen)},
              dx * dx * (1.0 + spread * U(gen)), 1.0 + spread * U(gen));
  if (variable_h) {
    f.w.hs.resize(f.P.size());
    for (auto& hh : f.w.hs) hh = 1.3 * dx * (1.0 + 0.2 * U(gen));
  }
  f.finish(1.3 * dx, variable_h, "truncated_exponential");
}

// The matrices of every particle (all rows are fluid here); own_h: each particle's kernel at its own
// h (what the assembly sets with a variable h), else the pair's W_ij.
template <int D>
std::shared_ptr<IntegralApproachField<D>> matrices(PairTermFixture<D>& f, bool own_h = false) {
  auto C = std::make_shared<IntegralApproachField<D>>();
  if (own_h) C->kernel = kernel_info<D>("truncated_exponential").W;
  IntegralApproachMatrix<D>(C).apply(f.w);
  return C;
}

// Particles at least `margin` from the lattice's edge (n x n at spacing dx), whose supports are full.
bool interior(const PairTermFixture<2>& f, std::size_t i, int n, double dx, double margin) {
  for (int d = 0; d < 2; ++d)
    if (f.w.x[d][i] < margin || f.w.x[d][i] > (n - 1) * dx - margin) return false;
  return true;
}

}  // namespace

TEST_CASE("integral approach: the gradient of a linear field is exact on a distorted lattice", "[physics][integral_approach]") {
  const int n = 14;
  const double dx = 0.1;
  PairTermFixture<2> f;
  distorted_lattice(f, n, dx, 0.25, 0.3, 3);
  const auto C = matrices(f);
  // sum_j V_j (f_j - f_i) A_ij for f = 3 + 2 x - 5 y, at every particle (edges included: the matrix
  // is made from the same neighbours).
  const auto& w = f.w;
  double worst = 0.0;
  for (std::size_t i = 0; i < w.n; ++i) {
    double g[2] = {};
    for (std::uint32_t k = w.pairs.offset[i]; k < w.pairs.offset[i + 1]; ++k) {
      const std::uint32_t j = w.pairs.j[k];
      const double dxk[2] = {w.dx[0][k], w.dx[1][k]};
      double c[2];
      ia_times<2>(C->of(i), dxk, c);
      const double df = 2.0 * (w.x[0][j] - w.x[0][i]) - 5.0 * (w.x[1][j] - w.x[1][i]);
      for (int d = 0; d < 2; ++d) g[d] -= f.P.mass[j] / w.rho[j] * df * c[d] * w.W[k];
    }
    worst = std::max({worst, std::abs(g[0] - 2.0), std::abs(g[1] + 5.0)});
  }
  CHECK(worst < 1e-10);

  // The continuity terms in the linear velocity field v = G x: -rho div v = -rho tr G at every
  // particle with IA, and off by the lattice's quadrature error with grad W.
  const double G[2][2] = {{0.7, -0.4}, {0.9, -1.6}};
  for (std::size_t i = 0; i < w.n; ++i)
    for (int d = 0; d < 2; ++d) f.w.v[d][i] = G[d][0] * w.x[0][i] + G[d][1] * w.x[1][i];
  ContinuityDensityIA<2, true>(C).apply(f.w);
  std::vector<double> ia = f.drho;
  std::fill(f.drho.begin(), f.drho.end(), 0.0);
  ContinuityDensity<2, true>{}.apply(f.w);
  double worst_ia = 0.0, worst_std = 0.0;
  for (std::size_t i = 0; i < w.n; ++i) {
    const double exact = -w.rho[i] * (G[0][0] + G[1][1]);
    worst_ia = std::max(worst_ia, std::abs(ia[i] - exact));
    if (interior(f, i, n, dx, 4.0 * dx)) worst_std = std::max(worst_std, std::abs(f.drho[i] - exact));
  }
  CHECK(worst_ia < 1e-10);
  CHECK(worst_std > 1e-2);  // the kernel-gradient form, even with full supports

  // 1D: C is the scalar 1 / sum_j V_j x_ij^2 W_ij, and the slope of a linear field is exact.
  PairTermFixture<1> l;
  l.domain.lo = {-10.0};
  l.domain.hi = {10.0};
  l.domain.periodic = {false};
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int i = 0; i < 30; ++i) l.P.add(Kind::Fluid, {(i + 0.3 * U(gen)) * dx}, {0.0}, dx * (1.0 + 0.3 * U(gen)), 1.0);
  l.finish(1.3 * dx, false, "truncated_exponential");
  for (std::size_t i = 0; i < l.w.n; ++i) l.w.v[0][i] = -1.5 * l.w.x[0][i];
  const auto C1 = matrices(l);
  ContinuityDensityIA<1, true>(C1).apply(l.w);
  for (std::size_t i = 0; i < l.w.n; ++i) CHECK(l.drho[i] == Approx(1.5 * l.w.rho[i]).epsilon(1e-10));
}

TEST_CASE("integral approach: pair terms conserve momentum and total energy to round-off", "[physics][integral_approach]") {
  for (bool vh : {false, true}) {
    PairTermFixture<2> f;
    distorted_lattice(f, 9, 0.1, 0.3, 0.4, 11, vh);
    std::mt19937 gen(13);
    std::uniform_real_distribution<double> U(0.5, 1.5);
    for (std::size_t i = 0; i < f.w.n; ++i) {
      f.w.p[i] = U(gen);
      f.w.c[i] = U(gen);
      f.w.e[i] = U(gen);
    }
    const auto C = matrices(f, vh);
    PressureGradientIA<2>(C).apply(f.w);
    EnergyEquationIA<2>(C).apply(f.w);
    ArtificialViscosityIA<2, true>(MonaghanPi{1.0, 2.0, 0.1}, C).apply(f.w);
    ArtificialViscosityIA<2, true, SignalVelocityPi>(SignalVelocityPi{1.0, 2.0, 0.3, 0.25}, C).apply(f.w);
    ArtificialConductivityIA<2>(1.0, C).apply(f.w);
    double p[2] = {}, e = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < f.w.n; ++i) {
      const double m = f.P.mass[i];
      for (int d = 0; d < 2; ++d) {
        p[d] += m * f.dvdt[d][i];
        e += m * f.w.v[d][i] * f.dvdt[d][i];
        scale += m * std::abs(f.dvdt[d][i]);
      }
      e += m * f.de[i];
    }
    CHECK(scale > 1.0);  // the forces are not all zero
    CHECK(std::abs(p[0]) < 1e-13 * scale);
    CHECK(std::abs(p[1]) < 1e-13 * scale);
    CHECK(std::abs(e) < 1e-13 * scale);
  }
}

TEST_CASE("integral approach: the standard form on a regular isotropic lattice", "[physics][integral_approach]") {
  // A periodic square lattice: C is isotropic, and for the (tapered) Gaussian truncated_exponential
  // kernel, whose grad W = -(2 / h^2) W dx inside the taper, C W dx equals -grad W pair by pair up to
  // the taper's share of the second moment.
  const int n = 16;
  const double dx = 0.1;
  PairTermFixture<2> f;
  f.domain.lo = {0.0, 0.0};
  f.domain.hi = {n * dx, n * dx};
  f.domain.periodic = {true, true};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) f.P.add(Kind::Fluid, {(i + 0.5) * dx, (j + 0.5) * dx}, {0.0, 0.0}, dx * dx, 1.0);
  f.finish(1.3 * dx, false, "truncated_exponential");
  const auto C = matrices(f);
  const double h = f.h;
  for (std::size_t i = 0; i < f.w.n; ++i) {
    const double* Ci = C->of(i);
    CHECK(Ci[1] == Approx(0.0).margin(1e-12 * Ci[0]));
    CHECK(Ci[3] == Approx(Ci[0]).epsilon(1e-12));
    CHECK(Ci[0] * h * h / 2.0 == Approx(1.0).epsilon(1e-2));  // the taper's share of the second moment: 0.4 %
  }
  // A pressure wave p = 1 + 0.1 sin(2 pi x / L): the IA and kernel-gradient accelerations agree.
  for (std::size_t i = 0; i < f.w.n; ++i) f.w.p[i] = 1.0 + 0.1 * std::sin(2.0 * M_PI * f.w.x[0][i] / (n * dx));
  PressureGradientIA<2>(C).apply(f.w);
  const auto ia = f.dvdt;
  for (auto& a : f.dvdt) std::fill(a.begin(), a.end(), 0.0);
  PressureGradient117<2>{}.apply(f.w);
  double amax = 0.0, diff = 0.0;
  for (std::size_t i = 0; i < f.w.n; ++i) {
    amax = std::max(amax, std::abs(f.dvdt[0][i]));
    diff = std::max({diff, std::abs(ia[0][i] - f.dvdt[0][i]), std::abs(ia[1][i] - f.dvdt[1][i])});
  }
  CHECK(amax > 0.1);
  CHECK(diff < 2e-3 * amax);
}

TEST_CASE("integral approach: the pressure force on a graded lattice with a varying h", "[physics][integral_approach]") {
  // A 1D line whose spacing grows by 3 % a particle (equal masses, rho = m / dx, h = 1.3 dx: the
  // x-spacing and h of an expansion fan), p = rho^1.4. The IA momentum equation gives -(1/rho) dp/dx
  // to 0.2 % with each particle's own h and to 0.2 % with the pair's h_ij; the kernel-gradient form
  // of Vukčević 2012, eq 117 misses by 1.4 %.
  PairTermFixture<1> f;
  f.domain.lo = {-100.0};
  f.domain.hi = {100.0};
  f.domain.periodic = {false};
  const int n = 80;
  const double m = 0.01, growth = 1.03;
  std::vector<double> spacing;
  double x = 0.0, dx = m;
  for (int i = 0; i < n; ++i) {
    f.P.add(Kind::Fluid, {x}, {0.0}, m, m / dx);
    spacing.push_back(dx);
    x += dx;
    dx *= growth;
  }
  f.w.hs.resize(n);
  for (int i = 0; i < n; ++i) f.w.hs[i] = 1.3 * spacing[i];
  f.finish(1.3 * m, true, "truncated_exponential");
  for (int i = 0; i < n; ++i) f.w.p[i] = std::pow(f.w.rho[i], 1.4);
  double err[3] = {}, scale = 0.0;  // IA own h, IA h_ij, kernel gradient
  for (int mode = 0; mode < 3; ++mode) {
    for (auto& a : f.dvdt[0]) a = 0.0;
    if (mode < 2) PressureGradientIA<1>(matrices(f, mode == 0)).apply(f.w);
    else PressureGradient117<1>{}.apply(f.w);
    // Away from the ends (full supports); -(1/rho) dp/dx by central differences over the neighbours
    // (second order on the geometric lattice, well below the errors compared).
    for (int i = 20; i < n - 20; ++i) {
      const double dpdx = (f.w.p[i + 1] - f.w.p[i - 1]) / (f.w.x[0][i + 1] - f.w.x[0][i - 1]);
      const double exact = -dpdx / f.w.rho[i];
      scale = std::max(scale, std::abs(exact));
      err[mode] = std::max(err[mode], std::abs(f.dvdt[0][i] - exact));
    }
  }
  CHECK(err[0] < 5e-3 * scale);
  CHECK(err[1] < 5e-3 * scale);
  CHECK(err[2] > 1e-2 * scale);
}

TEST_CASE("integral approach: ghost images carry their source's matrix mirrored", "[physics][integral_approach]") {
  // A square lattice above a free-slip ghost wall at y = 0, periodic in x, gas at rest at uniform p:
  // fluid and images together form one regular lattice, so every fluid particle's pressure force
  // vanishes when each image has its source's matrix mirrored. An image's own row (no images of
  // images) would give it the matrix of half a support.
  const int nx = 12, ny = 14;
  const double dx = 0.1, h = 1.3 * dx;
  Particles<2> P;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) P.add(Kind::Fluid, {(i + 0.5) * dx, (j + 0.5) * dx}, {0.0, 0.0}, dx * dx, 1.0);
  P.n_fluid = P.size();
  Domain<2> dom;
  dom.lo = {0.0, -1.0};
  dom.hi = {nx * dx, 2.0};
  dom.periodic = {true, false};
  Workspace<2> w;
  load_workspace(w, P, dom, h);
  BoxWalls<2> walls{};
  walls[1][0].present = true;
  walls[1][0].position = 0.0;
  walls[1][0].no_slip = false;
  GhostGenerator<2> gen(walls, TruncatedExponentialKernel<2>::support);
  gen.generate(P.size(), P, w);
  REQUIRE(gen.count() > 0);
  for (std::size_t i = 0; i < w.n; ++i) w.p[i] = 1.0;
  PairList verlet;
  build_workspace_pairs<2, TruncatedExponentialKernel<2>>(w, P, dom, TruncatedExponentialKernel<2>::support * h, verlet);
  std::array<std::vector<double>, 2> dvdt;
  for (auto& a : dvdt) a.assign(w.n, 0.0);
  for (int d = 0; d < 2; ++d) w.dvdt[d] = dvdt[d].data();
  auto C = std::make_shared<IntegralApproachField<2>>();
  IntegralApproachMatrix<2>(C, [&gen] { return gen.base(); }).apply(w);
  GhostIntegralApproachMatrix<2>(&gen, C).apply(w);
  PressureGradientIA<2>(C).apply(w);
  double amax = 0.0;
  // Rows next to the wall, below those whose neighbours' supports reach the lattice's open top.
  std::size_t checked = 0;
  for (std::size_t i = 0; i < w.n_fluid; ++i) {
    if (w.x[1][i] > ny * dx - 2.0 * TruncatedExponentialKernel<2>::support * h) continue;
    amax = std::max({amax, std::abs(dvdt[0][i]), std::abs(dvdt[1][i])});
    ++checked;
  }
  CHECK(checked >= 3 * nx);
  CHECK(amax < 1e-9);
  // Each image's matrix is its source's with the off-diagonal sign flipped (the mirror y -> -y).
  for (std::size_t g = 0; g < gen.count(); ++g) {
    const double* Cs = C->of(gen.sources()[g]);
    const double* Cg = C->of(gen.base() + g);
    CHECK(Cg[0] == Approx(Cs[0]).epsilon(1e-14));
    CHECK(Cg[1] == Approx(-Cs[1]).margin(1e-12 * Cs[0]));
    CHECK(Cg[3] == Approx(Cs[3]).epsilon(1e-14));
  }
}
