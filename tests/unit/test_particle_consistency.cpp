// Discrete particle-consistency sums (Vukčević 2012, eqs 90-91) on lattices, perturbed lattices and
// next to a wall.
#include <catch2/catch.hpp>

#include <cmath>

#include "sphmol/analysis/particle_consistency.hpp"
#include "sphmol/analysis/particle_sets.hpp"
#include "sphmol/kernels/registry.hpp"

using namespace sphmol::analysis;

TEST_CASE("cubic B-spline with h = d is an exact partition of unity on a 1D lattice", "[consistency]") {
  // B-splines reproduce constants and linear functions on their knot lattice at ANY point,
  // so eqs 90 and 91 hold exactly (and the gradient sums too).
  const auto k = sphmol::kernel_info<1>("cubic_spline");
  const double d = 0.3;
  const auto set = regular_lattice<1>(6, d);
  for (double x : {0.0, 0.37 * d, -0.81 * d}) {
    const auto s = consistency_sums<1>(set, {x}, d, k);
    CHECK(s.S0 == Approx(1.0).epsilon(1e-14));
    CHECK(std::abs(s.S1[0]) < 1e-15);
    CHECK(std::abs(s.G0[0]) < 1e-13);
    CHECK(s.G1[0][0] == Approx(1.0).epsilon(1e-13));
  }
}

template <int D>
void check_sets(const char* name, double s0_tol) {
  const auto k = sphmol::kernel_info<D>(name);
  const double d = 1.0, h = 1.3;
  std::array<double, D> x{};
  INFO(name << " " << D << "D");
  // Regular lattice, interior particle: odd sums vanish by symmetry, S0 is close to 1.
  const auto reg = consistency_sums<D>(regular_lattice<D>(6, d), x, h, k);
  CHECK(std::abs(reg.S0 - 1.0) < s0_tol);
  for (int a = 0; a < D; ++a) {
    CHECK(std::abs(reg.S1[a]) < 1e-14);
    CHECK(std::abs(reg.G0[a]) < 1e-14);
  }
  // Perturbed lattice: deterministic for a seed, and the odd sums no longer vanish.
  const auto p1 = perturbed_lattice<D>(6, d, 0.2, 42), p2 = perturbed_lattice<D>(6, d, 0.2, 42),
             p3 = perturbed_lattice<D>(6, d, 0.2, 43);
  CHECK(p1.x == p2.x);
  CHECK(p1.x != p3.x);
  const auto per = consistency_sums<D>(p1, x, h, k);
  double s1 = 0.0;
  for (int a = 0; a < D; ++a) s1 += std::abs(per.S1[a]);
  CHECK(s1 > 1e-3);
  // Wall: half of the support is cut off, eqs 90-91 fail badly.
  const auto wall = consistency_sums<D>(wall_lattice<D>(6, d), x, h, k);
  CHECK(wall.S0 < 0.8);
  CHECK(wall.S1[0] < -0.1 * h);  // the missing particles are all on the -x_1 side
  CHECK(wall.neighbours < reg.neighbours);
}

TEST_CASE("consistency sums on regular, perturbed and wall particle sets", "[consistency]") {
  check_sets<2>("quintic_morris", 2e-4);
  check_sets<3>("quintic_morris", 2e-3);
  check_sets<2>("wendland_c2", 2e-2);
}
