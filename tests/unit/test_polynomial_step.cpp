// The C^m polynomial step of core/polynomial_step.hpp (the dynamic walls' density floor): the
// regularised incomplete beta function, C^m and not C^(m+1) at both ends, monotone, the smooth max
// built on it, and (AVX2) four lanes equal to the scalar bit for bit.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "sphmol/core/polynomial_step.hpp"

using namespace sphmol;

namespace {
double binomial(int n, int k) {
  double b = 1.0;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return b;
}
}  // namespace

TEST_CASE("polynomial step: 0 below 0, 1 above 1, symmetric", "[smooth_step]") {
  for (double t : {-1e300, -2.0, -1e-300, -0.0, 0.0}) CHECK(polynomial_step(t) == 0.0);
  for (double t : {1.0, 1.0 + 1e-15, 3.0, 1e300}) CHECK(polynomial_step(t) == 1.0);
  CHECK(polynomial_step(std::numeric_limits<double>::quiet_NaN()) == 0.0);
  CHECK(polynomial_step(0.5) == Approx(0.5).epsilon(1e-15));
  for (int k = 1; k < 1000; ++k) {
    const double t = k / 1000.0, s = polynomial_step(t);
    CHECK(s + polynomial_step(1.0 - t) == Approx(1.0).epsilon(1e-15));
    // P' = (2m + 1) binom(2m, m) (t (1 - t))^m against a central difference.
    constexpr int m = kPolynomialStepOrder;
    const double e = 1e-6, dp = (2 * m + 1) * binomial(2 * m, m) * std::pow(t * (1.0 - t), m);
    CHECK((polynomial_step(t + e) - polynomial_step(t - e)) / (2 * e) == Approx(dp).epsilon(1e-6).margin(1e-9));
  }
}

TEST_CASE("polynomial step: monotone on a fine grid, in [0, 1]", "[smooth_step]") {
  double prev = 0.0;
  for (int k = 0; k <= 100000; ++k) {
    const double s = polynomial_step(k / 100000.0);
    CHECK(s >= prev);
    CHECK(s <= 1.0);
    prev = s;
  }
}

TEST_CASE("polynomial step: the regularised incomplete beta I_t(m + 1, m + 1) (Olver et al. 2010, eq 8.17.5)", "[smooth_step]") {
  // The binomial sum of Olver et al. 2010, eq 8.17.5, against the code's form t^(m+1) sum_j binom(m + j, j) (1 - t)^j.
  constexpr int m = kPolynomialStepOrder, n = 2 * m + 1;
  for (int k = 0; k <= 1000; ++k) {
    const double t = k / 1000.0;
    double bernstein = 0.0;
    for (int j = m + 1; j <= n; ++j) bernstein += binomial(n, j) * std::pow(t, j) * std::pow(1.0 - t, n - j);
    CHECK(polynomial_step(t) == Approx(bernstein).epsilon(1e-13).margin(1e-15));
  }
}

TEST_CASE("polynomial step is C^m at both ends and not C^(m+1)", "[smooth_step]") {
  // C^m with a jump of the (m + 1)-th derivative at t = 0 means P(t) = a t^(m+1) + O(t^(m+2)) with
  // a = P^(m+1)(0+) / (m + 1)! != 0, here binom(2m + 1, m): P(t) / t^(m+1) -> a and P(t) / P(2t) ->
  // 2^-(m+1) (a C-infinity step falls below every power, a C^(m-1) one stays at 2^-m). The end t = 1
  // the same, through 1 - P(1 - t).
  constexpr int m = kPolynomialStepOrder;
  const double a = binomial(2 * m + 1, m);
  for (double t : {1e-2, 5e-3}) {  // the next term is about -m t of the first
    INFO("t = " << t);
    CHECK(polynomial_step(t) / std::pow(t, m + 1) == Approx(a).epsilon(8 * t));
    CHECK((1.0 - polynomial_step(1.0 - t)) / std::pow(t, m + 1) == Approx(a).epsilon(8 * t));
    CHECK(polynomial_step(t) / polynomial_step(2 * t) == Approx(std::pow(2.0, -(m + 1))).epsilon(8 * t));
  }
  // Relative accuracy near 0 (no cancellation): P(1e-3) is 1716e-21 to the next term.
  CHECK(polynomial_step(1e-3) == Approx(a * std::pow(1e-3, m + 1)).epsilon(8e-3));
}

TEST_CASE("smooth max(x, 0): exact outside the band, in [0, x] inside, width 0 is the kink", "[smooth_step]") {
  const double w = 0.3;
  for (double x : {5.0, 0.3, 0.3 + 1e-12}) CHECK(smooth_max0(x, w) == x);
  for (double x : {0.0, -1e-300, -0.1, -7.0}) CHECK(smooth_max0(x, w) == 0.0);
  for (double x : {0.29, 0.15, 0.01}) {
    CHECK(smooth_max0(x, w) > 0.0);
    CHECK(smooth_max0(x, w) < x);
  }
  for (double x : {-2.0, -1e-300, 0.0, 1e-300, 3.0}) CHECK(smooth_max0(x, 0.0) == std::max(x, 0.0));
  // rho0 + smooth_max0(rho - rho0, 0) is rho or rho0 exactly (Sterbenz: rho - rho0 is exact within a
  // factor 2), the plain floor max(rho, rho0) of dynamic walls.
  for (double rho : {999.0, 1000.0, 1000.0 + 1e-10, 1003.7}) CHECK(1000.0 + smooth_max0(rho - 1000.0, 0.0) == std::max(rho, 1000.0));
}

#if defined(__AVX2__)
TEST_CASE("polynomial step: four lanes equal the scalar bit for bit", "[smooth_step]") {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> t;
  for (int k = -20; k <= 1020; ++k) t.push_back(k / 1000.0 + 1e-7 * (k % 3));
  for (double x : {-0.0, 0.0, 1e-300, 1e-3, 1.0 - 1e-16, 1.0, 1.0 + 1e-16, inf, -inf, nan, 0.5, 0.25}) t.push_back(x);
  t.resize(t.size() & ~std::size_t{3});
  for (std::size_t k = 0; k + 4 <= t.size(); k += 4) {
    alignas(32) double out[4];
    _mm256_store_pd(out, polynomial_step_lanes(_mm256_loadu_pd(t.data() + k)));
    for (int l = 0; l < 4; ++l) {
      const double s = polynomial_step(t[k + l]);
      INFO("argument " << t[k + l]);
      CHECK(std::memcmp(&out[l], &s, sizeof s) == 0);
    }
  }
}
#endif
