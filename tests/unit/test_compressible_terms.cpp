// Compressible-flow terms (Niedoba 2012, §2.2.4-2.2.5) on small particle sets: exactness on uniform and
// linear fields, signs, and the pair antisymmetry that conserves momentum and total energy.
#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>

#include "sphmol/core/state_layout.hpp"
#include "sphmol/physics/artificial_conductivity.hpp"
#include "sphmol/physics/artificial_viscosity.hpp"
#include "sphmol/physics/continuity_density.hpp"
#include "sphmol/physics/energy_equation.hpp"
#include "sphmol/physics/eos_ideal_gas.hpp"
#include "sphmol/physics/normalised_summation_density.hpp"
#include "sphmol/physics/pressure_gradient.hpp"
#include "sphmol/physics/pressure_gradient_116.hpp"
#include "sphmol/physics/smoothing_length_rate.hpp"
#include "sphmol/physics/summation_density.hpp"
#include "sphmol/rhs/kernel_pass.hpp"
#include "sphmol/rhs/kernel_pass_variable_h.hpp"

#include "pair_term_fixture.hpp"

using namespace sphmol;

namespace {

template <int D>
using Fixture = PairTermFixture<D>;

// Periodic 1D line of n particles at spacing dx with density rho (m = rho dx).
// (Fixtures are filled in place: the workspace points into them.)
void periodic_line(Fixture<1>& f, int n, double dx, double rho) {
  f.domain.lo = {0.0};
  f.domain.hi = {n * dx};
  f.domain.periodic = {true};
  for (int i = 0; i < n; ++i) f.P.add(Kind::Fluid, {(i + 0.5) * dx}, {0.0}, rho * dx, rho);
  f.finish(1.3 * dx);
}

// Random 2D cloud (open domain) with random velocities, densities, pressures, energies.
void random_cloud(Fixture<2>& f, unsigned seed, bool variable_h) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  f.domain.lo = {-1.0, -1.0};
  f.domain.hi = {2.0, 2.0};
  f.domain.periodic = {false, false};
  const double dx = 0.1;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i)
      f.P.add(Kind::Fluid, {(i + 0.3 * U(gen)) * dx, (j + 0.3 * U(gen)) * dx}, {U(gen) - 0.5, U(gen) - 0.5},
              0.5 + U(gen), 0.5 + U(gen));
  if (variable_h) {
    f.w.hs.resize(f.P.size());
    for (auto& hh : f.w.hs) hh = 0.13 * (0.8 + 0.4 * U(gen));
  }
  f.finish(0.13, variable_h);
  for (std::size_t i = 0; i < f.P.size(); ++i) {
    f.w.p[i] = 0.5 + U(gen);
    f.w.c[i] = 1.0 + U(gen);
  }
}

double momentum_rate(const Fixture<2>& f, int d) {
  double s = 0.0;
  for (std::size_t i = 0; i < f.P.size(); ++i) s += f.P.mass[i] * f.dvdt[d][i];
  return s;
}
// d/dt sum m (e + v^2/2)
double energy_rate(const Fixture<2>& f) {
  double s = 0.0;
  for (std::size_t i = 0; i < f.P.size(); ++i)
    s += f.P.mass[i] * (f.de[i] + f.w.v[0][i] * f.dvdt[0][i] + f.w.v[1][i] * f.dvdt[1][i]);
  return s;
}
double abs_force(const Fixture<2>& f) {
  double s = 0.0;
  for (std::size_t i = 0; i < f.P.size(); ++i) s += f.P.mass[i] * (std::abs(f.dvdt[0][i]) + std::abs(f.dvdt[1][i]));
  return s;
}

// An open line of 41 particles at spacing 0.1 and density 2 (h = 0.13), in the uniform strain u = a x.
void open_line_in_uniform_strain(Fixture<1>& g, double a) {
  g.domain.lo = {-10.0};
  g.domain.hi = {10.0};
  g.domain.periodic = {false};
  for (int i = 0; i < 41; ++i) g.P.add(Kind::Fluid, {(i - 20) * 0.1}, {0.0}, 2.0 * 0.1, 2.0);
  g.finish(0.13);
  for (std::size_t i = 0; i < g.P.size(); ++i) g.w.v[0][i] = a * g.w.x[0][i];
}

}  // namespace

TEST_CASE("state layout holds only the configured blocks, in order", "[state]") {
  StateLayout<2> L;
  L.n = 10;
  CHECK(L.size() == 40);
  CHECK(L.field_names() == std::vector<std::string>{"position", "velocity"});
  L.has_density = L.has_energy = L.has_smoothing_length = true;
  CHECK(L.size() == 70);
  CHECK(L.density() == 40);
  CHECK(L.energy() == 50);
  CHECK(L.smoothing_length() == 60);
  CHECK(L.field_names() == std::vector<std::string>{"position", "velocity", "density", "energy", "smoothing_length"});
  L.has_density = false;
  CHECK(L.energy() == 40);
  CHECK(L.smoothing_length() == 50);
  CHECK(L.field_names() == std::vector<std::string>{"position", "velocity", "energy", "smoothing_length"});
}

TEST_CASE("continuity density: zero for uniform motion, -rho div v for a linear field, sign", "[physics]") {
  Fixture<1> f;
  periodic_line(f, 40, 0.1, 2.0);
  for (auto& v : f.w.v[0]) v = 3.0;
  ContinuityDensity<1>{}.apply(f.w);
  for (double r : f.drho) CHECK(r == Approx(0.0).margin(1e-12));

  // Open line, u = a x: interior particles see drho/dt = -rho a (compression for a < 0 raises rho).
  Fixture<1> g;
  const double a = -0.7;
  open_line_in_uniform_strain(g, a);
  ContinuityDensity<1>{}.apply(g.w);
  CHECK(g.drho[20] > 0.0);
  CHECK(g.drho[20] == Approx(-2.0 * a).epsilon(5e-2));  // lattice quadrature error of the kernel moment ~2 %
}

TEST_CASE("pressure gradients 116 and 117: zero for uniform p, right sign, momentum conserved", "[physics]") {
  for (int form = 0; form < 2; ++form) {
    Fixture<1> f;
  periodic_line(f, 40, 0.1, 1.0);
    for (auto& p : f.w.p) p = 5.0;
    std::unique_ptr<Term<1>> t;
    if (form == 0) t = std::make_unique<PressureGradient116<1>>();
    else t = std::make_unique<PressureGradient117<1>>();
    t->apply(f.w);
    for (double a : f.dvdt[0]) CHECK(a == Approx(0.0).margin(1e-10));

    // p = p0 - k x on an open line: interior acceleration -(1/rho) dp/dx = +k.
    Fixture<1> g;
    g.domain.lo = {-10.0};
    g.domain.hi = {10.0};
    g.domain.periodic = {false};
    for (int i = 0; i < 41; ++i) g.P.add(Kind::Fluid, {(i - 20) * 0.1}, {0.0}, 0.1, 1.0);
    g.finish(0.13);
    for (std::size_t i = 0; i < g.P.size(); ++i) g.w.p[i] = 10.0 - 2.0 * g.w.x[0][i];
    t->apply(g.w);
    CHECK(g.dvdt[0][20] == Approx(2.0).epsilon(5e-2));  // lattice quadrature error of the kernel moment ~2 %
  }
  for (bool vh : {false, true}) {
    Fixture<2> c1;
  random_cloud(c1, 7, vh);
    PressureGradient116<2>{}.apply(c1.w);
    CHECK(momentum_rate(c1, 0) == Approx(0.0).margin(1e-10 * abs_force(c1)));
    CHECK(momentum_rate(c1, 1) == Approx(0.0).margin(1e-10 * abs_force(c1)));
    Fixture<2> c2;
  random_cloud(c2, 8, vh);
    PressureGradient117<2>{}.apply(c2.w);
    CHECK(momentum_rate(c2, 0) == Approx(0.0).margin(1e-10 * abs_force(c2)));
    CHECK(momentum_rate(c2, 1) == Approx(0.0).margin(1e-10 * abs_force(c2)));
  }
}

TEST_CASE("energy equations 2.66/2.65 conserve total energy with their momentum forms", "[physics]") {
  for (bool vh : {false, true}) {
    Fixture<2> f;
  random_cloud(f, 11, vh);
    PressureGradient117<2>{}.apply(f.w);
    EnergyEquation<2, EnergyForm::symmetric_117>{}.apply(f.w);
    CHECK(energy_rate(f) == Approx(0.0).margin(1e-10 * abs_force(f)));
    Fixture<2> g;
  random_cloud(g, 12, vh);
    PressureGradient116<2>{}.apply(g.w);
    EnergyEquation<2, EnergyForm::symmetric_116>{}.apply(g.w);
    CHECK(energy_rate(g) == Approx(0.0).margin(1e-10 * abs_force(g)));
    // Mismatched forms do not conserve: the test can fail.
    Fixture<2> m;
  random_cloud(m, 13, vh);
    PressureGradient116<2>{}.apply(m.w);
    EnergyEquation<2, EnergyForm::symmetric_117>{}.apply(m.w);
    CHECK(std::abs(energy_rate(m)) > 1e-6 * abs_force(m));
  }
}

namespace {
// The viscosity terms' common checks on a random cloud: they act, conserve momentum and energy, and
// turn kinetic energy into heat.
void check_conserves_and_heats(const Fixture<2>& f) {
  CHECK(abs_force(f) > 0.0);
  CHECK(momentum_rate(f, 0) == Approx(0.0).margin(1e-10 * abs_force(f)));
  CHECK(momentum_rate(f, 1) == Approx(0.0).margin(1e-10 * abs_force(f)));
  CHECK(energy_rate(f) == Approx(0.0).margin(1e-10 * abs_force(f)));
  double heat = 0.0;
  for (std::size_t i = 0; i < f.P.size(); ++i) heat += f.P.mass[i] * f.de[i];
  CHECK(heat > 0.0);
}

// Two particles of mass `m` a distance `gap` apart on a line, at velocities s and -s (s > 0:
// approaching), with densities `rho`; smoothing length = gap.
void two_particle_line(Fixture<1>& g, double gap, double s, double m, std::array<double, 2> rho) {
  g.domain.lo = {-1.0};
  g.domain.hi = {1.0};
  g.domain.periodic = {false};
  g.P.add(Kind::Fluid, {-gap / 2}, {s}, m, rho[0]);
  g.P.add(Kind::Fluid, {gap / 2}, {-s}, m, rho[1]);
  g.finish(gap);
}
}  // namespace

TEST_CASE("artificial viscosity: momentum and energy conserved, heats, only approaching pairs", "[physics]") {
  Fixture<2> f;
  random_cloud(f, 21, true);
  ArtificialViscosity<2, true>(1.0, 1.0, 0.1).apply(f.w);
  check_conserves_and_heats(f);

  // Two particles approaching: decelerated (a of the left one < 0); receding: untouched.
  for (double s : {1.0, -1.0}) {
    Fixture<1> g;
    two_particle_line(g, 0.1, s, 1.0, {1.0, 1.0});
    ArtificialViscosity<1, false>(1.0, 1.0, 0.1).apply(g.w);
    if (s > 0) {
      CHECK(g.dvdt[0][0] < 0.0);
      CHECK(g.dvdt[0][1] == Approx(-g.dvdt[0][0]));
    } else {
      CHECK(g.dvdt[0][0] == 0.0);
    }
  }
}

TEST_CASE("signal-velocity viscosity (Monaghan 1997): conserves, heats, the pair value of its formula", "[physics]") {
  Fixture<2> f;
  random_cloud(f, 22, true);
  ArtificialViscosity<2, true, SignalVelocityPi>(SignalVelocityPi{1.0, 2.0}).apply(f.w);
  check_conserves_and_heats(f);
  // Two particles 0.05 apart approaching at 2 s (w = -2): Pi = -alpha (cbar - beta w / 2) w / rhobar with
  // cbar = 1.5, rhobar = 1.5, alpha = 1, beta = 2: Pi = 3.5 * 2 / 1.5; a_0 = -m Pi F dx.
  for (double s : {1.0, -1.0}) {
    Fixture<1> g;
    two_particle_line(g, 0.05, s, 0.7, {1.0, 2.0});
    g.w.c = {1.0, 2.0};
    ArtificialViscosity<1, false, SignalVelocityPi>(SignalVelocityPi{1.0, 2.0}).apply(g.w);
    if (s > 0) {
      const double pi = (1.5 + 2.0) * 2.0 / 1.5;
      const std::size_t k = 0;  // the one pair of row 0
      REQUIRE(g.w.pairs.offset[1] == 1);
      CHECK(g.dvdt[0][0] == Approx(-0.7 * pi * g.w.F[k] * g.w.dx[0][k]));
      CHECK(g.dvdt[0][0] < 0.0);
      CHECK(g.dvdt[0][1] == Approx(-g.dvdt[0][0]));
    } else {
      CHECK(g.dvdt[0][0] == 0.0);
      CHECK(g.dvdt[0][1] == 0.0);
    }
  }
}

// Random internal energies on the random cloud (the fixture's e is uniform).
void random_energy(Fixture<2>& f, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> U(0.5, 2.0);
  for (auto& e : f.w.e) e = U(gen);
}

TEST_CASE("artificial conductivity (Price 2008): zero for uniform e or p, conserves energy, heat flows downhill", "[physics]") {
  {  // uniform e (random p): no conduction
    Fixture<2> f;
    random_cloud(f, 31, true);
    ArtificialConductivity<2>(1.0).apply(f.w);
    for (const double de : f.de) CHECK(de == 0.0);
  }
  {  // uniform p (random e): v_sig^u = 0, no conduction (a contact in pressure balance stays sharp)
    Fixture<2> f;
    random_cloud(f, 32, true);
    random_energy(f, 33);
    f.w.p.assign(f.P.size(), 0.7);
    ArtificialConductivity<2>(1.0).apply(f.w);
    for (const double de : f.de) CHECK(de == 0.0);
  }
  {  // random e and p: the energy exchanged sums to zero, and it is not zero everywhere
    Fixture<2> f;
    random_cloud(f, 34, true);
    random_energy(f, 35);
    ArtificialConductivity<2>(1.0).apply(f.w);
    double total = 0.0, magnitude = 0.0;
    for (std::size_t i = 0; i < f.P.size(); ++i) {
      total += f.P.mass[i] * f.de[i];
      magnitude += f.P.mass[i] * std::abs(f.de[i]);
    }
    CHECK(magnitude > 0.0);
    CHECK(total == Approx(0.0).margin(1e-12 * magnitude));
    // Linear in alpha_u.
    Fixture<2> g;
    random_cloud(g, 34, true);
    random_energy(g, 35);
    ArtificialConductivity<2>(0.25).apply(g.w);
    for (std::size_t i = 0; i < f.P.size(); ++i) CHECK(g.de[i] == Approx(0.25 * f.de[i]).margin(1e-14));
  }
  {  // two particles: the hotter one cools at the rate of the formula, the colder one heats
    Fixture<1> g;
    g.domain.lo = {-1.0};
    g.domain.hi = {1.0};
    g.domain.periodic = {false};
    g.P.add(Kind::Fluid, {-0.025}, {0.0}, 0.7, 1.0);
    g.P.add(Kind::Fluid, {0.025}, {0.0}, 0.7, 2.0);
    g.finish(0.05);
    g.w.e = {3.0, 1.0};
    g.w.p = {1.2, 0.8};  // p_i - p_j = 0.4, rhobar = 1.5
    ArtificialConductivity<1>(1.0).apply(g.w);
    REQUIRE(g.w.pairs.offset[1] == 1);
    const double dWdr = g.w.F[0] * 0.05;  // F = (dW/dr) / r
    CHECK(dWdr < 0.0);
    CHECK(g.de[0] == Approx(0.7 / 1.5 * std::sqrt(0.4 / 1.5) * 2.0 * dWdr));
    CHECK(g.de[0] < 0.0);
    CHECK(g.de[1] == Approx(-g.de[0]));
  }
}

TEST_CASE("ideal gas EOS: p = (gamma-1) rho e and c = sqrt(gamma p / rho)", "[physics]") {
  Fixture<1> f;
  periodic_line(f, 8, 0.1, 0.25);
  for (std::size_t i = 0; i < 8; ++i) f.w.e[i] = 1.0 + i;
  IdealGasEos<1>(1.4).apply(f.w);
  for (std::size_t i = 0; i < 8; ++i) {
    CHECK(f.w.p[i] == Approx(0.4 * 0.25 * (1.0 + i)));
    CHECK(f.w.c[i] == Approx(std::sqrt(1.4 * f.w.p[i] / 0.25)));
  }
}

TEST_CASE("normalised summation density: exact on a uniform lattice, smaller edge deficit", "[physics]") {
  Fixture<1> f;
  periodic_line(f, 40, 0.1, 1.0);
  SummationDensity<1>{}.apply(f.w);
  const double plain = f.w.rho[5];
  NormalisedSummationDensity<1>{}.apply(f.w);
  CHECK(f.w.rho[5] == Approx(plain).epsilon(1e-12));

  Fixture<1> g;  // open line: the end particle misses half its neighbours
  g.domain.lo = {-10.0};
  g.domain.hi = {10.0};
  g.domain.periodic = {false};
  for (int i = 0; i < 30; ++i) g.P.add(Kind::Fluid, {i * 0.1}, {0.0}, 0.1, 1.0);
  g.finish(0.13);
  SummationDensity<1>{}.apply(g.w);
  const double edge_plain = g.w.rho[0], mid_plain = g.w.rho[15];
  NormalisedSummationDensity<1>{}.apply(g.w);
  // With the first-pass densities in the denominator the edge deficit shrinks (measured: 0.245 -> 0.183)
  // but does not vanish; it would only with the true rho_j there.
  CHECK(std::abs(g.w.rho[0] - mid_plain) < 0.8 * std::abs(edge_plain - mid_plain));
  CHECK(g.w.rho[15] == Approx(mid_plain).epsilon(1e-3));
}

TEST_CASE("smoothing length rate: dh/dt = -(h / (D rho)) drho/dt", "[physics]") {
  Fixture<2> f;
  random_cloud(f, 3, true);
  for (std::size_t i = 0; i < f.P.size(); ++i) f.drho[i] = 0.1 * i - 2.0;
  SmoothingLengthRate<2>{}.apply(f.w);
  for (std::size_t i = 0; i < f.P.size(); ++i) CHECK(f.dh[i] == Approx(-f.w.hs[i] / (2.0 * f.w.rho[i]) * f.drho[i]));
}

TEST_CASE("variable-h kernel pass: equals the constant pass for equal h, symmetric W_ij", "[kernel]") {
  Fixture<2> a;
  random_cloud(a, 5, false);
  Fixture<2> b;
  random_cloud(b, 5, false);
  b.w.hs.assign(b.P.size(), 0.13);
  b.finish(0.13, true);
  REQUIRE(a.w.pairs.j == b.w.pairs.j);
  for (std::size_t k = 0; k < a.w.pairs.pairs(); ++k) {
    CHECK(b.w.W[k] == Approx(a.w.W[k]).epsilon(1e-13));
    CHECK(b.w.F[k] == Approx(a.w.F[k]).epsilon(1e-13));
  }
  Fixture<2> c;
  random_cloud(c, 6, true);  // distinct h_i: W_ij == W_ji
  const auto& P = c.w.pairs;
  std::size_t checked = 0;
  for (std::size_t i = 0; i < P.rows(); ++i)
    for (std::uint32_t k = P.offset[i]; k < P.offset[i + 1]; ++k) {
      const std::uint32_t j = P.j[k];
      for (std::uint32_t q = P.offset[j]; q < P.offset[j + 1]; ++q)
        if (P.j[q] == i) {
          CHECK(c.w.W[q] == Approx(c.w.W[k]).epsilon(1e-14));
          CHECK(c.w.F[q] == Approx(c.w.F[k]).epsilon(1e-14));
          ++checked;
        }
    }
  CHECK(checked > 100);
}

// Colagrossi & Landrini (2003): drho_i/dt = rho_i sum_j (m_j / rho_j) v_ij . grad W_ij. On one density
// it is the mass-weighted sum; across a jump it gives the light particle the relative rate of the
// local div v, where the mass-weighted sum gives it rho_dense / rho_light times that.
TEST_CASE("continuity density with volume weights: equal to the mass form at one density, not amplified at a jump",
          "[physics]") {
  // Uniform density, u = a x: both forms agree to round-off.
  Fixture<1> g;
  open_line_in_uniform_strain(g, -0.7);
  ContinuityDensity<1>{}.apply(g.w);
  const std::vector<double> mass_form = g.drho;
  std::fill(g.drho.begin(), g.drho.end(), 0.0);
  ContinuityDensity<1, true>{}.apply(g.w);
  for (std::size_t i = 0; i < g.P.size(); ++i) CHECK(g.drho[i] == Approx(mass_form[i]).margin(1e-12));

  // Equal masses across a jump 1 -> 0.125 (spacings 0.1 and 0.8), the light side moving away at
  // speed 1: the first light particle's relative rate, (1 / rho) drho/dt.
  Fixture<1> f;
  f.domain.lo = {-10.0};
  f.domain.hi = {20.0};
  f.domain.periodic = {false};
  const double m = 0.1;
  for (int i = 0; i < 30; ++i) f.P.add(Kind::Fluid, {-(i + 0.5) * 0.1}, {0.0}, m, 1.0);
  const std::size_t first_light = f.P.size();
  for (int i = 0; i < 6; ++i) f.P.add(Kind::Fluid, {(i + 0.5) * 0.8}, {1.0}, m, 0.125);
  f.w.hs.assign(f.P.size(), 0.0);
  for (std::size_t i = 0; i < f.P.size(); ++i) f.w.hs[i] = 1.2 * m / f.P.rho[i];
  f.finish(0.12, true);
  ContinuityDensity<1>{}.apply(f.w);
  const double mass_rel = f.drho[first_light] / f.P.rho[first_light];
  std::fill(f.drho.begin(), f.drho.end(), 0.0);
  ContinuityDensity<1, true>{}.apply(f.w);
  const double vol_rel = f.drho[first_light] / f.P.rho[first_light];
  INFO("relative rates: mass " << mass_rel << ", volume " << vol_rel);
  CHECK(mass_rel < 0.0);  // it expands: the dense gas behind it stands still
  CHECK(vol_rel < 0.0);
  // Only the dense neighbours move relative to it; the mass form weights them by m_j = 8 rho_i V_j.
  CHECK(mass_rel == Approx(8.0 * vol_rel));
}
