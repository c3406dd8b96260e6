// Continuous moments (Vukčević 2012, eqs 64, 69) against values derived by hand.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "sphmol/analysis/kernel_moments.hpp"
#include "sphmol/kernels/registry.hpp"

using sphmol::analysis::kernel_moments;

TEST_CASE("moments of kernels with closed forms", "[moments]") {
  // Cubic B-spline with h = 1 is the density of a sum of 4 uniforms on [-1/2, 1/2]:
  // variance 4/12 = 1/3, fourth moment 3 (1/3)^2 - 4/120 = 3/10.
  const auto c1 = kernel_moments(sphmol::kernel_info<1>("cubic_spline"));
  CHECK(c1.M[0] == Approx(1.0).epsilon(1e-13));
  CHECK(c1.M[2] == Approx(1.0 / 3.0).epsilon(1e-12));
  CHECK(c1.M[4] == Approx(0.3).epsilon(1e-12));
  // Lucy 1D: (5/2)[B(3,4) + 3 B(4,4)] = 2/21.
  CHECK(kernel_moments(sphmol::kernel_info<1>("lucy")).M[2] == Approx(2.0 / 21.0).epsilon(1e-12));
  // Johnson 2D: M2 = (1/2) int r^2 W dA = 2 (3 - 24/5 + 2) = 2/5.
  CHECK(kernel_moments(sphmol::kernel_info<2>("quadratic_johnson")).M[2] == Approx(0.4).epsilon(1e-12));
  // Scaling: M_k is reported in units of h^k, so it does not depend on h.
  const auto w3a = kernel_moments(sphmol::kernel_info<3>("wendland_c2"), 1.0);
  const auto w3b = kernel_moments(sphmol::kernel_info<3>("wendland_c2"), 0.01);
  for (int k = 0; k <= 4; ++k) CHECK(w3a.M[k] == Approx(w3b.M[k]).epsilon(1e-10));
}

template <int D>
void check_derivative_moments() {
  for (const auto& e : sphmol::kernel_catalogue<D>()) {
    if (!e.available) continue;
    INFO(e.name << " in " << D << "D");
    const auto m = kernel_moments(e.info);
    CHECK(m.M[0] == Approx(e.info.mass).epsilon(1e-10));
    CHECK(m.dM[0] == 0.0);
    // Kernels that vanish at their support edge and have dW = d/dr W: M'_k = k M_(k-1) (eq 69 by parts).
    const bool jumps = e.name == "super_gaussian";
    if (e.info.derivative_is_exact && !jumps) {
      // M'_1 = M_0 and M''_2 = 2 M_0: 1 and 2 for every kernel but the unrenormalised truncated exponential.
      CHECK(m.dM[1] == Approx(m.M[0]).epsilon(1e-10));
      CHECK(m.dM[3] == Approx(3.0 * m.M[2]).epsilon(1e-10));
      // Eq 76: M''_2 = 2, and by parts M''_0 = 0, M''_4 = 12 M_2. (The 1D Johnson kernel has a
      // corner at r = 0, i.e. a delta in W'', which the volume integral leaves out; so does the
      // spiky kernel: any 1D kernel with W'(0) != 0.)
      if (D > 1 || e.info.dWdr(0.0, 1.0) == 0.0) {
        CHECK(std::abs(m.d2M[0]) < 1e-6);
        CHECK(m.d2M[2] == Approx(2.0 * m.M[0]).epsilon(1e-6));
        CHECK(m.d2M[4] == Approx(12.0 * m.M[2]).epsilon(1e-6));
      }
    } else if (jumps) {
      // The truncation at 3h leaves a surface term: M'_1 = M_0 - S_D (3h)^D W(3h) / D.
      const double S = D == 1 ? 2.0 : D == 2 ? 2.0 * std::numbers::pi : 4.0 * std::numbers::pi;
      CHECK(m.dM[1] == Approx(m.M[0] - S * std::pow(3.0, D) * e.info.W(3.0 - 1e-15, 1.0) / D).epsilon(1e-9));
    }
  }
}

TEST_CASE("derivative moments (eq 69) in every dimension", "[moments]") {
  check_derivative_moments<1>();
  check_derivative_moments<2>();
  check_derivative_moments<3>();
}

TEST_CASE("composite kernel derivative moment M'_1 from eq 13b", "[moments]") {
  // -pi int_0^h r^2 (13b) dr = 1369 k^2 (56k - 37) / (28 * 74 (74k - 63)); at k = 1: 26011/22792.
  const auto m = kernel_moments(sphmol::kernel_info<2>("composite"));
  CHECK(m.dM[1] == Approx(26011.0 / 22792.0).epsilon(1e-12));
}
