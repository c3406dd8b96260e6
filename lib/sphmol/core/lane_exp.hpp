#pragma once
// exp(u) with one sequence of operations for a double and for four doubles in an AVX2 vector, so a
// loop that calls it vectorises (std::exp is a library call) and its lanes give the scalar's numbers
// bit for bit. The reduction u = k ln 2 + r, |r| <= ln 2 / 2, with ln 2 in two parts (the first's
// trailing zeros make k C1 exact), exp(r) by the rational form of Moshier (1989, the Cephes library's
// exp: one division, seven multiply-adds), and 2^k put into the exponent bits. Within two ulp of
// std::exp (tests/unit/test_lane_exp.cpp); u is clamped to [-708, 708] (2^k stays a
// normal number), and u > 708 returns +inf, so exp(+inf) = inf and exp(-inf) = exp(-708) ~ 3e-308.
// The operations are plain multiplies and adds (the build's -ffp-contract=off keeps them unfused),
// so the scalar and the vector forms round alike.
#include <bit>
#include <cstdint>
#include <limits>
#include <type_traits>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace sphmol {

namespace lane_ops {
// a < b ? a : b and a > b ? a : b: the semantics of vminpd / vmaxpd (the second operand for NaN).
inline double min(double a, double b) { return a < b ? a : b; }
inline double max(double a, double b) { return a > b ? a : b; }
// a > b ? x : y
inline double select_gt(double a, double b, double x, double y) { return a > b ? x : y; }
// The double of bits (bits(a) + add) << 52: 2^k for a = 0x1.8p52 + k (below).
inline double exponent_bits(double a, std::int64_t add) {
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) + static_cast<std::uint64_t>(add)) << 52);
}
#if defined(__AVX2__)
inline __m256d min(__m256d a, __m256d b) { return _mm256_min_pd(a, b); }
inline __m256d max(__m256d a, __m256d b) { return _mm256_max_pd(a, b); }
inline __m256d splat_v(double a) { return _mm256_set1_pd(a); }
inline __m256d select_gt(__m256d a, __m256d b, __m256d x, __m256d y) {
  return _mm256_blendv_pd(y, x, _mm256_cmp_pd(a, b, _CMP_GT_OQ));
}
inline __m256d exponent_bits(__m256d a, std::int64_t add) {
  return _mm256_castsi256_pd(_mm256_slli_epi64(_mm256_add_epi64(_mm256_castpd_si256(a), _mm256_set1_epi64x(add)), 52));
}
#endif
// A constant in the lanes of V.
template <class V>
V constant(double a) {
#if defined(__AVX2__)
  if constexpr (!std::is_same_v<V, double>) return splat_v(a);
  else
#endif
    return a;
}
// t clamped to [0, 1], with -0.0 and NaN mapped to +0.0 (the steps' argument: a NaN from a zero-width
// band reads as t <= 0).
template <class V>
[[gnu::always_inline]] inline V clamp01(V t) {
  const V zero = constant<V>(0.0);
  return select_gt(t, zero, min(t, constant<V>(1.0)), zero);
}
}  // namespace lane_ops

template <class V>
[[gnu::always_inline]] inline V lane_exp(V u) {
  using namespace lane_ops;
  const auto c = [](double a) { return constant<V>(a); };
  constexpr double kBig = 708.0;
  const V x = max(min(u, c(kBig)), c(-kBig));
  // k = nearest integer to x / ln 2, as the low bits of shift + x log2(e) (their ulp is 1).
  constexpr double kShift = 0x1.8p52;
  const V ks = x * c(1.4426950408889634) + c(kShift);
  const V k = ks - c(kShift);
  const V r = (x - k * c(6.93145751953125e-1)) - k * c(1.42860682030941723212e-6);  // ln 2 = C1 + C2
  // exp(r) = 1 + 2 r P(r^2) / (Q(r^2) - r P(r^2)) (Moshier 1989, Cephes exp.c)
  const V rr = r * r;
  const V px = r * ((c(1.26177193074810590878e-4) * rr + c(3.02994407707441961300e-2)) * rr + c(9.99999999999999999910e-1));
  const V qx = ((c(3.00198505138664455042e-6) * rr + c(2.52448340349684104192e-3)) * rr + c(2.27265548208155028766e-1)) * rr +
               c(2.00000000000000000009e0);
  const V p = c(1.0) + c(2.0) * (px / (qx - px));
  // 2^k: the exponent field k + 1023 from the low bits of ks (bits(shift) has zeros in its low 12)
  const V e = p * exponent_bits(ks, 1023);
  return select_gt(u, c(kBig), c(std::numeric_limits<double>::infinity()), e);
}

}  // namespace sphmol
