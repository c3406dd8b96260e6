// The order-independent weighted RMS norm (time/fixed_point_norm.hpp): the same bits for any order
// and any split of the terms, within round-off of the plain sum, and infinite for a NaN.
#include <catch2/catch.hpp>

#include <nvector/nvector_openmp.h>
#include <nvector/nvector_serial.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include "sphmol/time/fixed_point_norm.hpp"

using namespace sphmol;

namespace {

double plain_wrms(const std::vector<double>& x, const std::vector<double>& w) {
  long double s = 0.0L;
  for (std::size_t i = 0; i < x.size(); ++i) s += static_cast<long double>(x[i] * w[i]) * (x[i] * w[i]);
  return static_cast<double>(std::sqrt(s / x.size()));
}

// The norm of the whole from the chunks of the parts [cuts[k], cuts[k+1]).
double split_wrms(const std::vector<double>& x, const std::vector<double>& w, const std::vector<std::size_t>& cuts) {
  double largest = 0.0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
    largest = std::max(largest, largest_weighted_square(x.data() + cuts[k], w.data() + cuts[k], cuts[k + 1] - cuts[k]));
  const int shift = fixed_point_shift(largest);
  FixedPointChunks all{};
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const auto part = fixed_point_squares(x.data() + cuts[k], w.data() + cuts[k], cuts[k + 1] - cuts[k], shift);
    for (int c = 0; c < 3; ++c) all[c] += part[c];
  }
  return fixed_point_wrms(all, shift, static_cast<double>(x.size()));
}

}  // namespace

TEST_CASE("fixed-point norm: the same bits for any order and split, close to the exact sum", "[time][norm]") {
  std::mt19937_64 rng(7);
  std::lognormal_distribution<double> mag(0.0, 6.0);  // terms over many decades
  std::uniform_int_distribution<int> sign(0, 1);
  const std::size_t n = 10007;
  std::vector<double> x(n), w(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = (sign(rng) ? 1.0 : -1.0) * mag(rng);
    w[i] = 1.0 / (1e-6 + 1e-3 * mag(rng));
  }
  const double whole = fixed_point_wrms(x.data(), w.data(), n);
  CHECK(whole == Approx(plain_wrms(x, w)).epsilon(1e-14));
  CHECK(split_wrms(x, w, {0, n}) == whole);
  CHECK(split_wrms(x, w, {0, 1, 5000, 5001, n}) == whole);
  CHECK(split_wrms(x, w, {0, 3333, 6666, n}) == whole);
  // A permutation of the entries: the same bits (a plain double sum changes in its last bits).
  std::vector<std::size_t> p(n);
  std::iota(p.begin(), p.end(), 0);
  std::shuffle(p.begin(), p.end(), rng);
  std::vector<double> xp(n), wp(n);
  for (std::size_t i = 0; i < n; ++i) xp[i] = x[p[i]], wp[i] = w[p[i]];
  CHECK(fixed_point_wrms(xp.data(), wp.data(), n) == whole);
}

TEST_CASE("fixed-point norm: zero, NaN and infinity", "[time][norm]") {
  std::vector<double> x(5, 0.0), w(5, 1.0);
  CHECK(fixed_point_wrms(x.data(), w.data(), 5) == 0.0);
  x[2] = std::numeric_limits<double>::quiet_NaN();
  CHECK(std::isinf(fixed_point_wrms(x.data(), w.data(), 5)));
  x[2] = std::numeric_limits<double>::infinity();
  CHECK(std::isinf(fixed_point_wrms(x.data(), w.data(), 5)));
  // A single tiny and a single huge term (squares near the ends of the double range).
  x.assign(5, 0.0);
  x[4] = 1e-150;
  CHECK(fixed_point_wrms(x.data(), w.data(), 5) / (1e-150 / std::sqrt(5.0)) == Approx(1.0).epsilon(1e-15));
  x[4] = 1e150;
  CHECK(fixed_point_wrms(x.data(), w.data(), 5) / (1e150 / std::sqrt(5.0)) == Approx(1.0).epsilon(1e-15));
}

TEST_CASE("fixed-point norm: serial and OpenMP vectors and their clones use it", "[time][norm]") {
  SUNContext ctx = nullptr;
  REQUIRE(SUNContext_Create(nullptr, &ctx) == 0);
  const sunindextype n = 1001;
  N_Vector s = N_VNew_Serial(n, ctx), o = N_VNew_OpenMP(n, 2, ctx), ws = N_VNew_Serial(n, ctx), wo = N_VNew_OpenMP(n, 2, ctx);
  for (sunindextype i = 0; i < n; ++i) {
    NV_Ith_S(s, i) = NV_Ith_OMP(o, i) = std::sin(0.37 * static_cast<double>(i)) * std::exp(0.01 * static_cast<double>(i));
    NV_Ith_S(ws, i) = NV_Ith_OMP(wo, i) = 1.0 / (1.0 + static_cast<double>(i % 17));
  }
  use_fixed_point_norm(s);
  use_fixed_point_norm(o);
  const double expect = fixed_point_wrms(N_VGetArrayPointer(s), N_VGetArrayPointer(ws), static_cast<std::size_t>(n));
  CHECK(N_VWrmsNorm(s, ws) == expect);
  CHECK(N_VWrmsNorm(o, wo) == expect);
  N_Vector c = N_VClone(o);
  N_VScale(1.0, o, c);
  CHECK(N_VWrmsNorm(c, wo) == expect);
  for (N_Vector v : {s, o, ws, wo, c}) N_VDestroy(v);
  SUNContext_Free(&ctx);
}

TEST_CASE("fixed-point dot product: the same bits for any order and split, close to the exact sum", "[time][norm]") {
  std::mt19937_64 rng(11);
  std::lognormal_distribution<double> mag(0.0, 3.0);
  std::uniform_int_distribution<int> sign(0, 1);
  const std::size_t n = 10007;
  std::vector<double> x(n), y(n);
  long double exact = 0.0L;
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = (sign(rng) ? 1.0 : -1.0) * mag(rng);
    y[i] = (sign(rng) ? 1.0 : -1.0) * mag(rng);
    exact += static_cast<long double>(x[i] * y[i]);
  }
  const double whole = fixed_point_dot(x.data(), y.data(), n);
  CHECK(whole == Approx(static_cast<double>(exact)).epsilon(1e-12));
  // The parts' chunks, summed as an MPI_SUM of 64-bit integers would sum them.
  for (const auto& cuts : {std::vector<std::size_t>{0, 1, 5000, 5001, n}, {0, 3333, 6666, n}}) {
    double largest = 0.0;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
      largest = std::max(largest, largest_product(x.data() + cuts[k], y.data() + cuts[k], cuts[k + 1] - cuts[k]));
    const int shift = fixed_point_shift(largest);
    FixedPointChunks all{};
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const auto part = fixed_point_products(x.data() + cuts[k], y.data() + cuts[k], cuts[k + 1] - cuts[k], shift);
      for (int c = 0; c < 3; ++c) all[c] += part[c];
    }
    CHECK(fixed_point_sum(all, shift) == whole);
  }
  std::vector<std::size_t> p(n);
  std::iota(p.begin(), p.end(), 0);
  std::shuffle(p.begin(), p.end(), rng);
  std::vector<double> xp(n), yp(n);
  for (std::size_t i = 0; i < n; ++i) xp[i] = x[p[i]], yp[i] = y[p[i]];
  CHECK(fixed_point_dot(xp.data(), yp.data(), n) == whole);
  // A negative sum, zero and a NaN.
  for (auto& v : y) v = -v;
  CHECK(fixed_point_dot(x.data(), y.data(), n) == -whole);
  std::vector<double> z(n, 0.0);
  CHECK(fixed_point_dot(x.data(), z.data(), n) == 0.0);
  z[3] = std::numeric_limits<double>::quiet_NaN();
  CHECK(std::isnan(fixed_point_dot(x.data(), z.data(), n)));
}

TEST_CASE("fixed-point dot product replaces a serial vector's and its clones'", "[time][norm]") {
  SUNContext ctx = nullptr;
  REQUIRE(SUNContext_Create(nullptr, &ctx) == 0);
  const std::size_t n = 4097;
  N_Vector a = N_VNew_Serial(static_cast<sunindextype>(n), ctx);
  use_fixed_point_dot(a);
  N_Vector b = N_VClone(a);
  double* x = N_VGetArrayPointer(a);
  double* y = N_VGetArrayPointer(b);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = std::sin(0.37 * static_cast<double>(i)) * std::exp(0.01 * static_cast<double>(i % 97));
    y[i] = std::cos(0.11 * static_cast<double>(i));
  }
  CHECK(N_VDotProd(a, b) == fixed_point_dot(x, y, n));
  CHECK(N_VDotProd(b, a) == fixed_point_dot(x, y, n));
  N_VDestroy(b);
  N_VDestroy(a);
  SUNContext_Free(&ctx);
}

namespace {

// The grid sum as the definition states it: each term scaled by ldexp, truncated to a 128-bit
// integer, summed modulo 2^128, cut into the three 48-bit chunks.
FixedPointChunks reference_grid_sum(const std::vector<double>& terms, int shift) {
  unsigned __int128 sum = 0;
  for (const double t : terms) sum += static_cast<unsigned __int128>(static_cast<__int128>(std::ldexp(t, shift)));
  const std::uint64_t chunk = (std::uint64_t{1} << 48) - 1;
  return {static_cast<std::uint64_t>(sum) & chunk, static_cast<std::uint64_t>(sum >> 48) & chunk,
          static_cast<std::uint64_t>(sum >> 96)};
}

}  // namespace

TEST_CASE("fixed-point sums equal the ldexp and 128-bit definition at every scale", "[time][norm]") {
  // The terms are x_i y_i with y_i = 1 (and squares (x_i w_i)^2 with w_i = 1): decades from the
  // subnormals to the top of the double range, signs mixed, more terms than one 64-bit block holds.
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  std::uniform_int_distribution<int> sign(0, 1);
  const std::size_t n = 40000;
  for (const int top : {1000, 300, 95, 40, 0, -60, -500, -900, -1000, -1070}) {
    // Exponents within 120 of the top (some terms fall below the grid) and a few far below.
    std::uniform_int_distribution<int> e(std::max(top - 120, -1074), top);
    std::vector<double> x(n), ones(n, 1.0), terms(n), squares(n);
    for (std::size_t i = 0; i < n; ++i) {
      const int k = i % 97 == 0 ? std::max(top - 400, -1074) : e(rng);
      x[i] = (sign(rng) ? 1.0 : -1.0) * std::ldexp(mantissa(rng), k);
      if (x[i] == 0.0 || !std::isfinite(x[i])) x[i] = std::ldexp(1.0, top);
      terms[i] = x[i] * ones[i];
    }
    // Blocks full of the largest value with one sign: the 64-bit block sums are at their widest (more
    // than 2^15 such terms would overflow one 64-bit sum).
    for (std::size_t i = 0; i < 36000; ++i) x[i] = terms[i] = std::ldexp(1.999, top);
    const double largest = largest_product(x.data(), ones.data(), n);
    const int shift = fixed_point_shift(largest);
    INFO("top exponent " << top << ", shift " << shift);
    CHECK(fixed_point_products(x.data(), ones.data(), n, shift) == reference_grid_sum(terms, shift));
    if (top <= 500 && top >= -500) {
      std::vector<double> r(n);
      for (std::size_t i = 0; i < n; ++i) {
        r[i] = std::sqrt(std::abs(x[i]));
        squares[i] = r[i] * r[i];
      }
      const int s2 = fixed_point_shift(largest_weighted_square(r.data(), ones.data(), n));
      CHECK(fixed_point_squares(r.data(), ones.data(), n, s2) == reference_grid_sum(squares, s2));
    }
  }
}
