// Hydrostatic kernel analysis (Potapov & Reshetnikova 2021, eqs 17-22): lattice formula vs a brute-force particle
// block, closed-form sums, and the root/verdict machinery.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "sphmol/analysis/hydrostatic_error.hpp"
#include "sphmol/kernels/registry.hpp"

using namespace sphmol::analysis;

TEST_CASE("lattice formula agrees with a brute-force SPH block", "[hydrostatic]") {
  for (const char* name : {"cubic_spline", "quintic_morris", "gaussian", "composite", "wendland_c2", "lucy"}) {
    const auto k = sphmol::kernel_info<2>(name);
    for (double kc : {0.8, 0.97, 1.1, 1.23})
      for (double ap : {std::sqrt(3.0) / 2.0, 1.0}) {
        INFO(name << " k = " << kc << " a_p = " << ap);
        const auto lat = hydrostatic_errors(k, kc, ap);
        const auto blk = hydrostatic_errors_block(k, kc, ap, 0.02, 1000.0, 9.81, 0.1);
        CHECK(std::abs(lat.eps_rho - blk.eps_rho) < 1e-12);
        CHECK(std::abs(lat.eps_gradp - blk.eps_gradp) < 1e-12);
        // The errors do not depend on d, rho0, g or the depth.
        const auto blk2 = hydrostatic_errors_block(k, kc, ap, 1.0, 1.0, 1.0, 0.0);
        CHECK(std::abs(blk2.eps_rho - blk.eps_rho) < 1e-12);
        CHECK(std::abs(blk2.eps_gradp - blk.eps_gradp) < 1e-12);
      }
  }
}

TEST_CASE("closed-form lattice sums for a kernel of radius h", "[hydrostatic]") {
  // Poly6 (support h = k d): for k <= 1 only the particle itself is inside, for 1 < k < sqrt 3
  // exactly the six nearest neighbours at distance d, four of them at |dy| = sqrt(3)/2 d, so
  //   eps_rho = a_p (W(0) + 6 W(d)) d^2 - 1,  eps_gradP = -a_p d^2 * 4 * (3/4) d W'(d) - 1.
  const auto k = sphmol::kernel_info<2>("muller_poly6");
  const double s = 4.0 / std::numbers::pi, ap = std::numbers::pi / 4.0;
  for (double kc : {0.8, 0.95}) {
    const auto e = hydrostatic_errors(k, kc, ap);
    CHECK(e.eps_rho == Approx(ap * s / (kc * kc) - 1.0).epsilon(1e-14));
    CHECK(e.eps_gradp == -1.0);
  }
  for (double kc : {1.05, 1.2, 1.5}) {
    const double q = 1.0 / kc, t = 1.0 - q * q;
    const double W0 = s / (kc * kc), W1 = s / (kc * kc) * t * t * t, dW1 = -6.0 * s / (kc * kc * kc) * q * t * t;
    const auto e = hydrostatic_errors(k, kc, ap);
    CHECK(e.eps_rho == Approx(ap * (W0 + 6.0 * W1) - 1.0).epsilon(1e-13));
    CHECK(e.eps_gradp == Approx(-ap * 3.0 * dW1 - 1.0).epsilon(1e-13));
  }
}

TEST_CASE("shell coefficients of Potapov & Reshetnikova 2021, eqs 18 and 21 for R = 2", "[hydrostatic]") {
  // Wendland C2 at k = 1.1 (support 2.2 d): shells d, sqrt3 d, 2d (6 nodes each). Eq 21's bracket
  // 2 sqrt3 (W'(d) + 2 W'(2d)) + 6 W'(sqrt3 d) times Delta y/d = sqrt3/2 gives 3, 6, 3 sqrt3.
  const auto k = sphmol::kernel_info<2>("wendland_c2");
  const double kc = 1.1, ap = std::sqrt(3.0) / 2.0, s3 = std::sqrt(3.0);
  auto W = [&](double r) { return k.W(r, kc); };
  auto dW = [&](double r) { return k.dWdr(r, kc); };
  const auto e = hydrostatic_errors(k, kc, ap);
  CHECK(e.eps_rho == Approx(ap * (W(0) + 6.0 * (W(1) + W(2) + W(s3))) - 1.0).epsilon(1e-13));
  CHECK(e.eps_gradp == Approx(-ap * (3.0 * dW(1) + 6.0 * dW(2) + 3.0 * s3 * dW(s3)) - 1.0).epsilon(1e-13));
}

TEST_CASE("roots and condition 22", "[hydrostatic]") {
  for (const auto& e : sphmol::kernel_catalogue<2>()) {
    for (double ap : {std::sqrt(3.0) / 2.0, std::numbers::pi / 4.0, 1.0}) {
      const auto row = hydrostatic_row(e.info, ap);
      INFO(e.name << " a_p = " << ap);
      for (const auto& r : row.rho_roots) {
        CHECK(r.k >= 0.75);
        CHECK(r.k <= 1.25);
        const auto err = hydrostatic_errors(e.info, r.k, ap);
        CHECK(std::abs(err.eps_rho) < 1e-9);
        CHECK(err.eps_gradp == Approx(r.other));
      }
      for (const auto& r : row.gradp_roots) {
        const auto err = hydrostatic_errors(e.info, r.k, ap);
        CHECK(std::abs(err.eps_gradp) < 1e-9);
        CHECK(err.eps_rho == Approx(r.other));
      }
      // best_k really is (near) the minimax point of the scan.
      double worst_min = 1e300;
      for (int i = 0; i <= 500; ++i) {
        const auto err = hydrostatic_errors(e.info, 0.75 + 0.5 * i / 500, ap);
        worst_min = std::min(worst_min, std::max(std::abs(err.eps_rho), std::abs(err.eps_gradp)));
      }
      CHECK(row.best_err <= worst_min + 1e-15);
      CHECK(row.passes == (row.best_err <= 0.01));
    }
  }
  // A kernel with a sign change of eps_rho that is a jump, not a root, is not reported: the
  // composite kernel's eps_gradP has a pole at k = 63/74 (eq 13b) and must not appear as a root.
  const auto comp = hydrostatic_row(sphmol::kernel_info<2>("composite"), std::sqrt(3.0) / 2.0);
  for (const auto& r : comp.gradp_roots) CHECK(std::abs(r.k - 63.0 / 74.0) > 1e-3);
}
