// The dam-break formulation's pieces: Wendland C2 in DualSPHysics' convention, delta-SPH density
// diffusion (Molteni & Colagrossi 2009), dynamic boundary particles (Crespo et al. 2007) with their
// densities in the ODE state, and the Tait EOS's local sound speed.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <numbers>
#include <random>

#include "sphmol/boundary/dynamic_wall_density.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/kernels/wendland_c2.hpp"
#include "sphmol/physics/density_diffusion.hpp"
#include "sphmol/physics/eos_tait.hpp"
#include "sphmol/reference/dam_break_front.hpp"
#include "sphmol/cases/case_module.hpp"

#include "workspace_pairs.hpp"

using namespace sphmol;

TEST_CASE("Wendland C2 uses DualSPHysics' h: support 2h, alpha_D = 7/(4 pi h^2), 21/(16 pi h^3)", "[kernel][dam_break]") {
  // DualSPHysics (Crespo et al. 2015, CPC 187:204, eq. 4): W = alpha_D (1 - q/2)^4 (2q + 1), q = r/h, 0 <= q <= 2,
  // with h = coefh sqrt(2) dp in 2D; so smoothing_ratio 1.414 reproduces its h, not a kappa h.
  const double pi = std::numbers::pi, h = 0.01414;
  for (double q : {0.0, 0.3, 0.99, 1.5, 1.999}) {
    const double f = std::pow(1.0 - 0.5 * q, 4) * (2.0 * q + 1.0);
    CHECK(WendlandC2Kernel<2>::W(q * h, h) == Approx(7.0 / (4.0 * pi * h * h) * f).epsilon(1e-13));
    CHECK(WendlandC2Kernel<3>::W(q * h, h) == Approx(21.0 / (16.0 * pi * h * h * h) * f).epsilon(1e-13));
  }
  CHECK(WendlandC2Kernel<2>::support == 2.0);
  CHECK(WendlandC2Kernel<2>::W(2.0 * h, h) == 0.0);
}

namespace {
// A jittered 2D fluid patch (optionally over one row of wall particles) with pairs and kernel values.
struct Patch {
  Particles<2> P;
  Domain<2> dom;
  Workspace<2> w;
  PairList verlet;
  std::vector<double> drho, drho_wall;
  double dx = 0.1, h = 0.1414;

  Patch(int n, bool wall_row, double jitter, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-jitter * dx, jitter * dx), r(990.0, 1010.0);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) P.add(Kind::Fluid, {(i + 0.5) * dx + u(rng), (j + 0.5) * dx + u(rng)}, {0, 0}, 10.0, r(rng));
    if (wall_row)
      for (int i = -2; i < n + 2; ++i) P.add(Kind::Wall, {(i + 0.5) * dx, -0.5 * dx}, {0, 0}, 10.0, 1000.0, {0, 1}, 0.5 * dx);
    dom.lo = {-1.0, -1.0};
    dom.hi = {2.0, 2.0};
    w.n = P.size();
    w.n_fluid = P.n_fluid;
    w.n_wall_density = P.n_wall();
    w.particles = &P;
    w.domain = &dom;
    w.h = h;
    for (int d = 0; d < 2; ++d) {
      w.x[d] = P.x[d];
      w.v[d] = P.v[d];
    }
    w.rho = P.rho;
    w.hs.assign(w.n, h);
    drho.assign(P.n_fluid, 0.0);
    drho_wall.assign(P.n_wall(), 0.0);
    w.drhodt = drho.data();
    w.drhodt_wall = drho_wall.data();
  }
  void pairs() { build_workspace_pairs<2, WendlandC2Kernel<2>>(w, P, dom, 2.0 * h, verlet); }
};

// A density diffusion whose pair terms are antisymmetric with the volumes m / rho: sum_i V_i D_i = 0.
void check_volume_weighted_sum_zero(const Patch& p) {
  double s = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < p.P.n_fluid; ++i) {
    s += p.P.mass[i] / p.w.rho[i] * p.drho[i];
    scale += std::abs(p.P.mass[i] / p.w.rho[i] * p.drho[i]);
  }
  CHECK(scale > 0.0);
  CHECK(std::abs(s) <= 1e-12 * scale);
}
}  // namespace

TEST_CASE("delta-SPH diffusion: zero on uniform density, conserves sum V_i drho_i, smooths a bump", "[physics][dam_break]") {
  Patch p(8, true, 0.2, 3);
  p.pairs();
  const DensityDiffusion<2> diff(0.1, p.h, 50.0);
  // Uniform density: nothing to diffuse (walls at another density must not matter: fluid pairs only).
  for (std::size_t i = 0; i < p.P.n_fluid; ++i) p.w.rho[i] = 1003.0;
  diff.apply(p.w);
  for (double r : p.drho) CHECK(r == 0.0);
  // Random density: the pair terms are antisymmetric with the volumes m/rho, so sum_i V_i D_i = 0.
  for (std::size_t i = 0; i < p.P.n_fluid; ++i) p.w.rho[i] = p.P.rho[i];
  diff.apply(p.w);
  check_volume_weighted_sum_zero(p);
  // A single denser particle loses density, its neighbours gain.
  std::fill(p.drho.begin(), p.drho.end(), 0.0);
  for (std::size_t i = 0; i < p.P.n_fluid; ++i) p.w.rho[i] = 1000.0;
  const std::size_t c = 4 * 8 + 4;
  p.w.rho[c] = 1010.0;
  diff.apply(p.w);
  CHECK(p.drho[c] < 0.0);
  CHECK(p.drho[c + 1] > 0.0);
  CHECK(p.drho[c + 8] > 0.0);
}

namespace {
// The column at rest of a constant sound speed c under gravity g (t >= ramp): drho/dy = -rho g / c^2,
// rho = rho0 exp(g (top - y) / c^2); the patch's own rows, its top row a free surface.
void hydrostatic_column(Patch& p, double g, double c) {
  const double top = 8 * p.dx;
  for (std::size_t i = 0; i < p.w.n; ++i) {
    p.w.rho[i] = 1000.0 * std::exp(g * (top - p.w.x[1][i]) / (c * c));
    p.w.c[i] = c;
  }
}
double largest(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}
}  // namespace

TEST_CASE("hydrostatic density diffusion: nothing on a column at rest, the plain form drains its surface rows",
          "[physics][dam_break]") {
  Patch p(8, true, 0.0, 3);
  p.pairs();
  p.w.c.assign(p.w.n, 0.0);
  const double g = 9.81, c = 20.0, ramp = 1.0;
  hydrostatic_column(p, g, c);
  p.w.t = 2.0;
  const DensityDiffusion<2> plain(0.1, p.h, c);
  const HydrostaticDensityDiffusion<2> hydro(0.1, p.h, c, {0.0, -g}, ramp);
  plain.apply(p.w);
  const double drained = largest(p.drho);
  // The plain form moves density out of the rows that lack neighbours above or below (it does not
  // diffuse into the walls): the top row gains, the bottom row loses.
  CHECK(p.drho[7 * 8 + 3] > 0.0);
  CHECK(p.drho[3] < 0.0);
  std::fill(p.drho.begin(), p.drho.end(), 0.0);
  hydro.apply(p.w);
  // The pair rule is the mid-point rule of d rho / dy = -rho g / c^2: over a pair of height dy <= 2 h
  // (g dy / c^2 <= 7e-3) it misses rho (g dy / c^2)^3 / 12 <= 3e-5 kg/m^3 of the difference 6.9 kg/m^3.
  CHECK(largest(p.drho) < 1e-5 * drained);
  // While gravity ramps in, the column of the ramped g is the one at rest.
  p.w.t = 0.5;  // ramp factor (1 - cos(pi / 2)) / 2 = 1/2
  std::fill(p.drho.begin(), p.drho.end(), 0.0);
  hydro.apply(p.w);
  CHECK(largest(p.drho) > 0.1 * drained);
  hydrostatic_column(p, 0.5 * g, c);
  std::fill(p.drho.begin(), p.drho.end(), 0.0);
  hydro.apply(p.w);
  CHECK(largest(p.drho) < 1e-5 * drained);
}

TEST_CASE("hydrostatic density diffusion: the plain form without gravity, conserves sum V_i drho_i, damps alternate rows",
          "[physics][dam_break]") {
  Patch p(8, true, 0.2, 5);
  p.pairs();
  p.w.c.assign(p.w.n, 0.0);
  for (std::size_t i = 0; i < p.w.n; ++i) p.w.c[i] = 20.0 * std::sqrt(p.w.rho[i] / 1000.0);
  // No gravity: the plain form bit for bit.
  const DensityDiffusion<2> plain(0.1, p.h, 20.0);
  plain.apply(p.w);
  const std::vector<double> want = p.drho;
  std::fill(p.drho.begin(), p.drho.end(), 0.0);
  HydrostaticDensityDiffusion<2>(0.1, p.h, 20.0, {0.0, 0.0}, 0.0).apply(p.w);
  CHECK(p.drho == want);
  // With gravity the pair terms stay antisymmetric with the volumes m / rho: sum_i V_i D_i = 0.
  const HydrostaticDensityDiffusion<2> hydro(0.1, p.h, 20.0, {0.0, -9.81}, 0.0);
  std::fill(p.drho.begin(), p.drho.end(), 0.0);
  hydro.apply(p.w);
  check_volume_weighted_sum_zero(p);
  // Rows alternately denser and lighter than the column at rest (a pressure mode the symmetric
  // gradient does not see) are pulled back: each interior particle's rate opposes its row's offset.
  Patch q(8, true, 0.0, 3);
  q.pairs();
  q.w.c.assign(q.w.n, 0.0);
  hydrostatic_column(q, 9.81, 20.0);
  for (std::size_t i = 0; i < q.P.n_fluid; ++i) q.w.rho[i] += (i / 8) % 2 == 0 ? 0.01 : -0.01;
  HydrostaticDensityDiffusion<2>(0.1, q.h, 20.0, {0.0, -9.81}, 0.0).apply(q.w);
  for (std::size_t i = 0; i < q.P.n_fluid; ++i) CHECK(q.drho[i] * ((i / 8) % 2 == 0 ? 1.0 : -1.0) < 0.0);
}

TEST_CASE("dynamic wall particles: compressed by approaching fluid, relieved by receding fluid", "[boundary][dam_break]") {
  Patch p(6, true, 0.0, 5);
  p.pairs();
  const DynamicWallDensity<2> dbc;
  dbc.apply(p.w);
  for (double r : p.drho_wall) CHECK(r == 0.0);  // fluid at rest
  for (std::size_t i = 0; i < p.P.n_fluid; ++i) p.w.v[1][i] = -1.0;  // falling onto the wall
  dbc.apply(p.w);
  for (std::size_t k = 2; k < 8; ++k) CHECK(p.drho_wall[k] > 0.0);  // walls under the patch
  std::fill(p.drho_wall.begin(), p.drho_wall.end(), 0.0);
  for (std::size_t i = 0; i < p.P.n_fluid; ++i) p.w.v[1][i] = 1.0;
  dbc.apply(p.w);
  for (std::size_t k = 2; k < 8; ++k) CHECK(p.drho_wall[k] < 0.0);
}

TEST_CASE("dynamic wall particles: the density rate is continuous across the floor rho0", "[boundary][dam_break]") {
  // The EOS reads max(rho, rho0). The rate must not switch off at rho0 (it did: a decompressing wall at
  // the floor got 0 instead of its continuity rate), or f(t, y) jumps there and every fixed-step
  // integrator drops to first order in time.
  Patch p(6, true, 0.0, 5);
  p.pairs();
  for (std::size_t i = 0; i < p.P.n_fluid; ++i) p.w.v[1][i] = 1.0;  // receding from the wall
  const DynamicWallDensity<2> dbc;
  std::vector<double> above, at;
  for (double rho_w : {1000.0 * (1.0 + 1e-12), 1000.0}) {
    for (std::size_t k = p.P.n_fluid; k < p.w.n; ++k) p.w.rho[k] = rho_w;
    std::fill(p.drho_wall.begin(), p.drho_wall.end(), 0.0);
    dbc.apply(p.w);
    (rho_w > 1000.0 ? above : at) = p.drho_wall;
  }
  for (std::size_t k = 2; k < 8; ++k) {
    CHECK(above[k] < 0.0);
    CHECK(at[k] == Approx(above[k]).epsilon(1e-9));
  }
}

TEST_CASE("Tait EOS sets the local sound speed c0 (rho/rho0)^((gamma-1)/2)", "[physics][dam_break]") {
  Workspace<2> w;
  w.n = 3;
  w.rho = {1000.0, 1010.0, 990.0};
  w.p.assign(3, 0.0);
  w.c.assign(3, 0.0);
  TaitEos<2>(88.6, 1000.0, 7.0).apply(w);
  for (std::size_t i = 0; i < 3; ++i) {
    const double r = w.rho[i] / 1000.0;
    CHECK(w.c[i] == Approx(88.6 * std::pow(r, 3.0)).epsilon(1e-12));
    // c^2 = dp/drho, checked by a finite difference of p.
    const TaitLaw law(88.6, 1000.0, 7.0);
    const double dp = (law.pressure(w.rho[i] + 1e-4) - law.pressure(w.rho[i] - 1e-4)) / 2e-4;
    CHECK(w.c[i] * w.c[i] == Approx(dp).epsilon(1e-6));
  }
}

TEST_CASE("Tait EOS: a whole exponent by squaring agrees with pow, other exponents use pow", "[physics][dam_break]") {
  for (unsigned n : {1u, 2u, 3u, 7u, 8u, 15u, 64u})
    for (double x : {0.5, 0.97, 1.0, 1.0123, 1.3, 2.0}) {
      INFO("x = " << x << ", n = " << n);
      CHECK(TaitEos<2>::power(x, n) == Approx(std::pow(x, static_cast<double>(n))).epsilon(1e-14));
    }
  // gamma = 7 (squaring) and gamma = 7.5 (pow) against p = B((rho/rho0)^gamma - 1) from TaitLaw.
  for (double gamma : {7.0, 7.5}) {
    Workspace<2> w;
    w.n = 4;
    w.rho = {1000.0, 1010.0, 990.0, 1234.5};
    w.p.assign(4, 0.0);
    w.c.assign(4, 0.0);
    TaitEos<2>(88.6, 1000.0, gamma).apply(w);
    const TaitLaw law(88.6, 1000.0, gamma);
    for (std::size_t i = 0; i < 4; ++i) {
      INFO("gamma = " << gamma << ", rho = " << w.rho[i]);
      CHECK(w.p[i] == Approx(law.pressure(w.rho[i])).epsilon(1e-13).margin(1e-9));
      CHECK(w.c[i] == Approx(88.6 * std::pow(w.rho[i] / 1000.0, 0.5 * (gamma - 1.0))).epsilon(1e-13));
    }
  }
}

TEST_CASE("dam_break: wall densities are in the state and evolve, the scene has the expected particle counts", "[dam_break]") {
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml",
                               {"discretization.spacing=0.05"});
  auto sys = make_case<2>(c)->build(c);
  const auto& L = sys->layout();
  const auto& P = sys->particles();
  CHECK(P.n_fluid == 20u * 40u);
  CHECK(P.n_wall() == 2u * 60u + 82u);  // one layer: two side walls of 60 plus a bottom of 80 + 2 corners
  CHECK(L.n_wall_density == P.n_wall());
  CHECK(L.size() == 5 * P.n_fluid + P.n_wall());
  std::vector<double> y = sys->initial_state(), f(y.size());
  // Column in hydrostatic equilibrium: bottom fluid row compressed, top row at ~rho0.
  CHECK(y[L.density()] > 1000.0 * (1.0 + 0.5 * 1000.0 * 9.81 * 1.9 / (88.6 * 88.6 * 1000.0)));
  sys->rhs(0.0, y.data(), f.data());
  // Released at rest: the rates of the wall densities are those of a state at rest (zero).
  for (std::size_t k = 0; k < L.n_wall_density; ++k) CHECK(f[L.wall_density() + k] == 0.0);
  // The wall under the column holds it up: its pressure is the hydrostatic pressure (~rho0 g H).
  const std::size_t wall0 = P.n_fluid;  // bottom-left corner particle, under the column
  CHECK(sys->pressure()[wall0 + 2] == Approx(1000.0 * 9.81 * 2.025).epsilon(1e-3));
  // Moving the fluid down compresses the bottom walls.
  for (std::size_t i = 0; i < L.n; ++i) y[L.velocity(1) + i] = -0.1;
  sys->rhs(0.0, y.data(), f.data());
  CHECK(f[L.wall_density() + 2] > 0.0);
}

TEST_CASE("dam-break reference fronts: Martin & Moyce and Koshizuka & Oka interpolate inside their range only", "[reference][dam_break]") {
  CHECK(!interpolate_front(martin_moyce_1952_n2_2(), 0.5));
  CHECK(*interpolate_front(martin_moyce_1952_n2_2(), 0.832) == Approx(1.217));
  CHECK(*interpolate_front(koshizuka_oka_1996(), 0.0) == Approx(1.0));
  CHECK(*interpolate_front(koshizuka_oka_1996(), 0.5) == Approx(1.111 + (0.5 - 0.381) / (0.769 - 0.381) * 0.141));
  // Both experiments stay behind Ritter's front (Z = 1 + 2 T for H = 2a: x - a = 2 sqrt(gH) t).
  for (const auto& pt : martin_moyce_1952_n2_2()) CHECK(pt.Z < 1.0 + 2.0 * pt.T);
  for (const auto& pt : koshizuka_oka_1996()) CHECK(pt.Z <= 1.0 + 2.0 * pt.T);
}

TEST_CASE("dam_break config: new keys are checked and name the key", "[config][dam_break]") {
  const std::string file = std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml";
  auto error_of = [&](const std::vector<std::string>& sets) -> std::string {
    try {
      load_config(file, sets);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "<no error>";
  };
  CHECK(error_of({}) == "<no error>");
  CHECK_THAT(error_of({"discretization.density=summation", "discretization.density_diffusion=0"}),
             Catch::Contains("discretization.wall_pressure") && Catch::Contains("continuity"));
  CHECK_THAT(error_of({"discretization.wall_pressure=rest", "discretization.density=summation"}),
             Catch::Contains("discretization.density_diffusion") && Catch::Contains("continuity"));
  CHECK_THAT(error_of({"discretization.density_diffusion=-0.1"}), Catch::Contains("discretization.density_diffusion"));
  CHECK(error_of({"discretization.density_diffusion_form=hydrostatic_corrected"}) == "<no error>");
  CHECK_THAT(error_of({"discretization.density_diffusion_form=fourtakas"}),
             Catch::Contains("discretization.density_diffusion_form") && Catch::Contains("hydrostatic"));
  {
    // Without the diffusion the form is a notice, not an error.
    const auto off = load_config(file, {"discretization.density_diffusion_form=hydrostatic_corrected", "discretization.density_diffusion=0"});
    REQUIRE(off.notices.size() == 1);
    CHECK_THAT(off.notices[0], Catch::Contains("discretization.density_diffusion_form") && Catch::Contains("no effect"));
  }
  {
    const auto c = load_config(file, {"discretization.density_diffusion_form=hydrostatic_corrected"});
    CHECK(c.discretization.density_diffusion_form == "hydrostatic_corrected");
    const auto back = load_config_string(to_yaml(c));
    CHECK(back.discretization.density_diffusion_form == "hydrostatic_corrected");
    CHECK(to_yaml(load_config_string(to_yaml(back))) == to_yaml(back));
  }
  CHECK_THAT(error_of({"geometry.column=[5, 2]"}), Catch::Contains("geometry.column") && Catch::Contains("out of range"));
  CHECK_THAT(error_of({"geometry.column=[1]"}), Catch::Contains("geometry.column"));
  CHECK_THAT(error_of({"case=hydrostatic"}), Catch::Contains("geometry.column") && Catch::Contains("dam_break"));
}

TEST_CASE("Tait EOS: p and c of every particle are the per-particle formulas bit for bit, on 1, 2 and 3 threads",
          "[physics][dam_break][threads]") {
  // apply() works in runs of particles (TaitEos::kRun) with the power a sweep per bit of the exponent;
  // each particle must get exactly the numbers of the formulas: own rest densities for the first 150
  // of 203 particles (not a whole number of runs), rho0 for the rest; clamped or not; gamma 7 and 7.5.
  const std::size_t n = 203, n_own = 150;
  Particles<2> pt;
  for (std::size_t i = 0; i < n_own; ++i) pt.rest_density.push_back(i % 4 == 0 ? 1000.0 : 990.0 + 0.3 * static_cast<double>(i));
  std::vector<double> rho;
  for (std::size_t i = 0; i < n; ++i) rho.push_back(1000.0 * (1.0 + 0.03 * std::sin(0.7 * static_cast<double>(i))));
  const double c0 = 88.6, rho0 = 1000.0;
  for (const double gamma : {7.0, 7.5})
    for (const bool clamp : {false, true}) {
      const TaitLaw law(c0, rho0, gamma);
      const double c_ref = std::sqrt(law.B * law.gamma / law.rho0), floor = clamp ? 0.0 : -HUGE_VAL;
      const auto pow_g = [&](double r) { return gamma == 7.0 ? TaitEos<2>::power(r, 7) : std::pow(r, gamma); };
      std::vector<double> p_ref(n), c_ref_i(n);
      for (std::size_t i = 0; i < n; ++i) {
        const double r0 = i < n_own ? pt.rest_density[i] : rho0, r = rho[i] / r0, rg = pow_g(r);
        p_ref[i] = i < n_own ? std::max(floor, law.B / law.rho0 * r0 * (rg - 1.0)) : std::max(floor, law.B * (rg - 1.0));
        c_ref_i[i] = c_ref * std::sqrt(rg / r);
      }
      for (const int threads : {1, 2, 3}) {
        INFO("gamma " << gamma << " clamp " << clamp << " threads " << threads);
        Workspace<2> w;
        w.n = n;
        w.particles = &pt;
        w.rho = rho;
        w.p.assign(n, -1.0);
        w.c.assign(n, -1.0);
        const TaitEos<2> eos(c0, rho0, gamma, clamp);
#pragma omp parallel num_threads(threads)
        eos.apply(w);
        for (std::size_t i = 0; i < n; ++i) {
          INFO("particle " << i);
          CHECK(std::memcmp(&w.p[i], &p_ref[i], sizeof(double)) == 0);
          CHECK(std::memcmp(&w.c[i], &c_ref_i[i], sizeof(double)) == 0);
        }
      }
    }
}

TEST_CASE("dynamic wall particles: the EOS floor rho0 is smooth, exact outside its band", "[boundary][dam_break]") {
  // max(rho_wall, rho0) is a kink of f(t, y) that caps every fixed-step integrator at order 2; the EOS
  // reads rho0 + g(rho - rho0), g(x) = x S(x / (width rho0)): rho0 at or below rho0, rho above
  // rho0 (1 + width), in between strictly between (core/polynomial_step.hpp).
  const std::string file = std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml";
  auto wall_pressures = [&](const std::string& width, const std::vector<double>& rho) {
    const Config c = load_config(file, {"discretization.spacing=0.05", "discretization.wall_density_floor_width=" + width});
    auto sys = make_case<2>(c)->build(c);
    const auto& L = sys->layout();
    std::vector<double> y = sys->initial_state(), f(y.size());
    for (std::size_t k = 0; k < rho.size(); ++k) y[L.wall_density() + k] = rho[k];
    sys->rhs(0.0, y.data(), f.data());
    std::vector<double> p;
    for (std::size_t k = 0; k < rho.size(); ++k) p.push_back(sys->pressure()[sys->particles().n_fluid + k]);
    return p;
  };
  const double rho0 = 1000.0, w = 1e-4, band = w * rho0;
  const std::vector<double> rho{rho0 - 1.0, rho0, rho0 + 0.1 * band, rho0 + 0.5 * band, rho0 + 0.9 * band,
                                rho0 + band, rho0 + 2.0 * band, rho0 + 3.0};
  const auto sharp = wall_pressures("0", rho), smooth = wall_pressures("1e-4", rho);
  CHECK(sharp[0] == 0.0);
  CHECK(smooth[0] == 0.0);
  CHECK(smooth[1] == 0.0);
  for (std::size_t k = 2; k < 5; ++k) {
    INFO("rho - rho0 = " << rho[k] - rho0);
    CHECK(smooth[k] > 0.0);
    CHECK(smooth[k] < sharp[k]);
  }
  for (std::size_t k = 5; k < rho.size(); ++k) CHECK(smooth[k] == sharp[k]);
  // Deep in the band the smooth floor is flat to order m (core/polynomial_step.hpp; sharp: linear in rho - rho0).
  CHECK(sharp[2] / sharp[3] == Approx(0.2).epsilon(1e-3));
  CHECK(smooth[2] / smooth[3] < 1e-3);
}

TEST_CASE("wall_density_floor_width is refused where no wall is dynamic", "[config][dam_break]") {
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml",
                               {"discretization.spacing=0.05", "discretization.wall_pressure=rest",
                                "discretization.wall_density_floor_width=1e-3"});
  CHECK_THROWS_WITH(make_case<2>(c)->build(c), Catch::Contains("wall_density_floor_width") && Catch::Contains("no wall is dynamic"));
}
