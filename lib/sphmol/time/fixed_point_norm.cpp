#include "sphmol/time/fixed_point_norm.hpp"

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

// The terms term(i) on the grid of `shift`, truncated toward zero and summed modulo 2^128: ldexp by a
// power of two is exact (but for terms that fall below the smallest double), so the same term gives
// the same integer wherever it is added.
template <class Term>
FixedPointChunks grid_sum(std::size_t n, int shift, Term term) {
  unsigned __int128 sum = 0;
  for (std::size_t i = 0; i < n; ++i) sum += static_cast<unsigned __int128>(static_cast<__int128>(std::ldexp(term(i), shift)));
  return {static_cast<std::uint64_t>(sum) & kChunk, static_cast<std::uint64_t>(sum >> 48) & kChunk,
          static_cast<std::uint64_t>(sum >> 96)};
}

unsigned __int128 joined(const FixedPointChunks& c) {
  return static_cast<unsigned __int128>(c[0]) + (static_cast<unsigned __int128>(c[1]) << 48) +
         (static_cast<unsigned __int128>(c[2]) << 96);
}

}  // namespace

double largest_weighted_square(const double* x, const double* w, std::size_t n) {
  double largest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double p = x[i] * w[i];
    const double t = p * p;
    if (!(t <= std::numeric_limits<double>::max())) return std::numeric_limits<double>::infinity();
    largest = std::max(largest, t);
  }
  return largest;
}

int fixed_point_shift(double largest) { return kGridBits - 1 - std::ilogb(largest); }

FixedPointChunks fixed_point_squares(const double* x, const double* w, std::size_t n, int shift) {
  return grid_sum(n, shift, [&](std::size_t i) {
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
  double largest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = std::abs(x[i] * y[i]);
    if (!(t <= std::numeric_limits<double>::max())) return std::numeric_limits<double>::infinity();
    largest = std::max(largest, t);
  }
  return largest;
}

FixedPointChunks fixed_point_products(const double* x, const double* y, std::size_t n, int shift) {
  return grid_sum(n, shift, [&](std::size_t i) { return x[i] * y[i]; });
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
