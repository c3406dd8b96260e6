// The RKPM option of the consistency diagnostics restores linear consistency for the particle next
// to a wall, where the plain sums are off by tens of percent.
#include <catch2/catch.hpp>

#include "sphmol/analysis/corrected_consistency.hpp"

using namespace sphmol;
using namespace sphmol::analysis;

TEMPLATE_TEST_CASE_SIG("RKPM-corrected consistency sums are exact at a wall", "[analysis][rkpm]", ((int D), D), 1, 2, 3) {
  const double d = 1.0, h = 1.3;
  const auto wall = wall_lattice<D>(6, d);
  const std::array<double, D> x{};
  for (const char* name : {"cubic_spline", "quintic_morris", "wendland_c2"}) {
    const auto K = kernel_info<D>(name);
    const auto plain = consistency_sums<D>(wall, x, h, K, h / d);
    ConsistencySums<D> c;
    REQUIRE(rkpm_consistency_sums<D>(wall, x, h, K, h / d, c));
    CHECK(std::abs(plain.S0 - 1.0) > 0.05);
    CHECK(c.S0 == Approx(1.0).epsilon(1e-12));
    for (int a = 0; a < D; ++a) {
      CHECK(std::abs(c.S1[a]) < 1e-12);
      CHECK(std::abs(c.G0[a]) < 1e-10);
      for (int b = 0; b < D; ++b) CHECK(c.G1[a][b] == Approx(a == b ? 1.0 : 0.0).margin(1e-10));
    }
  }
}
