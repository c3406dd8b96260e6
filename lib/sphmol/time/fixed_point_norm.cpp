#include "sphmol/time/fixed_point_norm.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace sphmol {

namespace {

constexpr int kGridBits = 96;                      // the largest scaled term is below 2^96
constexpr std::uint64_t kChunk = (1ULL << 48) - 1;  // 48-bit chunks
constexpr double kMaxLength = 2147483648.0;         // 2^31 entries: the sum stays below 2^127

sunrealtype wrms_op(N_Vector x, N_Vector w) {
  return fixed_point_wrms(N_VGetArrayPointer(x), N_VGetArrayPointer(w), static_cast<std::size_t>(N_VGetLength(x)));
}

sunrealtype dot_op(N_Vector x, N_Vector y) {
  return fixed_point_dot(N_VGetArrayPointer(x), N_VGetArrayPointer(y), static_cast<std::size_t>(N_VGetLength(x)));
}

void require_serial(N_Vector v, const char* who) {
  const N_Vector_ID id = N_VGetVectorID(v);
  if (id != SUNDIALS_NVEC_SERIAL && id != SUNDIALS_NVEC_OPENMP)
    throw std::invalid_argument(std::string(who) + ": a serial or OpenMP vector is needed");
}

void check_length(std::size_t n) {
  if (static_cast<double>(n) >= kMaxLength) throw std::length_error("fixed-point sum: more than 2^31 entries");
}

// The terms term(i) on the grid of `shift`, truncated toward zero and summed modulo 2^128.
//
// Each scaled term v = term(i) 2^shift (|v| < 2^96) is formed by one or two multiplications by powers
// of two, exact as ldexp is (scaling up never rounds below the overflow the grid excludes; scaling
// down rounds only results below the smallest normal double, which truncate to 0 as ldexp's do).
// Its integer part is then split exactly in doubles, trunc(v) = a 2^48 + b with a = trunc(v 2^-48)
// and b = trunc(v - a 2^48): v 2^-48 and a 2^48 are exact, and v - a 2^48 is a multiple of v's ulp
// (at most 2^43) below 2^48 in magnitude, so it is exact too. |a|, |b| < 2^48 convert to 64-bit
// integers exactly (below), where a double -> 128-bit conversion and ldexp are library calls
// (they were a third of the instructions of arkode_imex on Couette, docs/performance.md). a and b are
// summed in 64-bit integers over blocks of 2^14 terms (below 2^62 in magnitude, so their modular sums
// are the exact sums) and the blocks in 128 bits: the same integer, modulo 2^128, as summing
// trunc(ldexp(term(i), shift)) one by one.
template <class Term>
FixedPointChunks grid_sum(std::size_t n, int shift, Term term) {
  // shift lies in [-928, 1169] (fixed_point_shift of a finite positive double): at most 2^1000 at once.
  const int first = std::min(shift, 1000);
  const double s1 = std::ldexp(1.0, first), s2 = std::ldexp(1.0, shift - first);
  constexpr double kDown = 0x1p-48, kUp = 0x1p48, kMagic = 0x1.8p52;
  constexpr std::uint64_t kMagicBits = std::bit_cast<std::uint64_t>(kMagic);
  constexpr std::size_t kBlock = std::size_t{1} << 14;
  __int128 high = 0, low = 0;
  for (std::size_t start = 0; start < n; start += kBlock) {
    const std::size_t end = std::min(n, start + kBlock);
    std::uint64_t h = 0, l = 0;  // modular sums of the block's a and b (exact: below 2^62)
    for (std::size_t i = start; i < end; ++i) {
      const double v = term(i) * s1 * s2;
      const double a = std::trunc(v * kDown);
      const double b = std::trunc(v - a * kUp);
      // a + 1.5 2^52 is exact for an integer |a| < 2^51 and lies in [2^52, 2^53), where the bit
      // pattern counts in units of 1: its pattern minus the constant's is a, modulo 2^64. Unlike a
      // double -> int64 conversion this vectorises with AVX2.
      h += std::bit_cast<std::uint64_t>(a + kMagic) - kMagicBits;
      l += std::bit_cast<std::uint64_t>(b + kMagic) - kMagicBits;
    }
    high += static_cast<std::int64_t>(h);
    low += static_cast<std::int64_t>(l);
  }
  const unsigned __int128 sum = (static_cast<unsigned __int128>(high) << 48) + static_cast<unsigned __int128>(low);
  return {static_cast<std::uint64_t>(sum) & kChunk, static_cast<std::uint64_t>(sum >> 48) & kChunk,
          static_cast<std::uint64_t>(sum >> 96)};
}

unsigned __int128 joined(const FixedPointChunks& c) {
  return static_cast<unsigned __int128>(c[0]) + (static_cast<unsigned __int128>(c[1]) << 48) +
         (static_cast<unsigned __int128>(c[2]) << 96);
}

}  // namespace

namespace {

// The largest term (every term is +0, positive or NaN), and +infinity if any is not finite. The
// terms' bit patterns as signed 64-bit integers order as the values do, and every pattern from
// +infinity up, or with the sign bit set (a NaN's may be), is not finite: an integer maximum and an
// OR of the patterns, which vectorise where a maximum of doubles (NaN-aware) does not.
template <class Term>
double largest_term(std::size_t n, Term term) {
  std::int64_t largest = 0;
  std::uint64_t any = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t bits = std::bit_cast<std::int64_t>(term(i));
    largest = bits > largest ? bits : largest;
    any |= static_cast<std::uint64_t>(bits);
  }
  constexpr std::int64_t kMaxFinite = std::bit_cast<std::int64_t>(std::numeric_limits<double>::max());
  if ((any >> 63) != 0 || largest > kMaxFinite) return std::numeric_limits<double>::infinity();
  return std::bit_cast<double>(largest);
}

}  // namespace

double largest_weighted_square(const double* x, const double* w, std::size_t n) {
  return largest_term(n, [x, w](std::size_t i) {
    const double p = x[i] * w[i];
    return p * p;
  });
}

int fixed_point_shift(double largest) { return kGridBits - 1 - std::ilogb(largest); }

FixedPointChunks fixed_point_squares(const double* x, const double* w, std::size_t n, int shift) {
  return grid_sum(n, shift, [x, w](std::size_t i) {
    const double p = x[i] * w[i];
    return p * p;
  });
}

double fixed_point_wrms(const FixedPointChunks& c, int shift, double length) {
  return std::sqrt(std::ldexp(static_cast<double>(joined(c)), -shift) / length);
}

double fixed_point_wrms(const double* x, const double* w, std::size_t n) {
  if (n == 0) return 0.0;
  check_length(n);
  const double largest = largest_weighted_square(x, w, n);
  if (largest == 0.0 || std::isinf(largest)) return std::sqrt(largest);
  const int shift = fixed_point_shift(largest);
  return fixed_point_wrms(fixed_point_squares(x, w, n, shift), shift, static_cast<double>(n));
}

double largest_product(const double* x, const double* y, std::size_t n) {
  return largest_term(n, [x, y](std::size_t i) { return std::abs(x[i] * y[i]); });
}

FixedPointChunks fixed_point_products(const double* x, const double* y, std::size_t n, int shift) {
  return grid_sum(n, shift, [x, y](std::size_t i) { return x[i] * y[i]; });
}

double fixed_point_sum(const FixedPointChunks& c, int shift) {
  // C++20: the conversion to the signed type is modulo 2^128, which gives back the signed sum.
  return std::ldexp(static_cast<double>(static_cast<__int128>(joined(c))), -shift);
}

double fixed_point_dot(const double* x, const double* y, std::size_t n) {
  if (n == 0) return 0.0;
  check_length(n);
  const double largest = largest_product(x, y, n);
  if (largest == 0.0) return 0.0;
  if (std::isinf(largest)) return std::numeric_limits<double>::quiet_NaN();
  const int shift = fixed_point_shift(largest);
  return fixed_point_sum(fixed_point_products(x, y, n, shift), shift);
}

double largest_magnitude(const double* v, std::size_t n) {
  return largest_term(n, [v](std::size_t i) { return std::abs(v[i]); });
}

FixedPointChunks fixed_point_values(const double* v, std::size_t n, int shift) {
  check_length(n);
  return grid_sum(n, shift, [v](std::size_t i) { return v[i]; });
}

double fixed_point_total(const double* v, std::size_t n) {
  if (n == 0) return 0.0;
  check_length(n);
  const double largest = largest_magnitude(v, n);
  if (largest == 0.0) return 0.0;
  if (std::isinf(largest)) return std::numeric_limits<double>::quiet_NaN();
  const int shift = fixed_point_shift(largest);
  return fixed_point_sum(fixed_point_values(v, n, shift), shift);
}

void use_fixed_point_norm(N_Vector v) {
  require_serial(v, "use_fixed_point_norm");
  v->ops->nvwrmsnorm = &wrms_op;
}

void use_fixed_point_dot(N_Vector v) {
  require_serial(v, "use_fixed_point_dot");
  v->ops->nvdotprod = &dot_op;
  v->ops->nvdotprodmulti = nullptr;
  v->ops->nvdotprodlocal = nullptr;
  v->ops->nvdotprodmultilocal = nullptr;
  v->ops->nvdotprodmultiallreduce = nullptr;
}

}  // namespace sphmol
