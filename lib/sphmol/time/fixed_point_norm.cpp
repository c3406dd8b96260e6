#include "sphmol/time/fixed_point_norm.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace sphmol {

namespace {

constexpr int kGridBits = 96;                      // the largest scaled term is below 2^96
constexpr std::uint64_t kChunk = (1ULL << 48) - 1;  // 48-bit chunks
constexpr double kMaxLength = 2147483648.0;         // 2^31 entries: the sum stays below 2^127

sunrealtype wrms_op(N_Vector x, N_Vector w) {
  return fixed_point_wrms(N_VGetArrayPointer(x), N_VGetArrayPointer(w), static_cast<std::size_t>(N_VGetLength(x)));
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
  unsigned __int128 sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double p = x[i] * w[i];
    // ldexp by a power of two is exact (but for terms that fall below the smallest double), and the
    // conversion truncates: the same integer for the same term wherever it is added.
    sum += static_cast<unsigned __int128>(std::ldexp(p * p, shift));
  }
  return {static_cast<std::uint64_t>(sum) & kChunk, static_cast<std::uint64_t>(sum >> 48) & kChunk,
          static_cast<std::uint64_t>(sum >> 96)};
}

double fixed_point_wrms(const FixedPointChunks& c, int shift, double length) {
  const unsigned __int128 sum = static_cast<unsigned __int128>(c[0]) + (static_cast<unsigned __int128>(c[1]) << 48) +
                                (static_cast<unsigned __int128>(c[2]) << 96);
  return std::sqrt(std::ldexp(static_cast<double>(sum), -shift) / length);
}

double fixed_point_wrms(const double* x, const double* w, std::size_t n) {
  if (n == 0) return 0.0;
  if (static_cast<double>(n) >= kMaxLength) throw std::length_error("fixed_point_wrms: more than 2^31 entries");
  const double largest = largest_weighted_square(x, w, n);
  if (largest == 0.0 || std::isinf(largest)) return std::sqrt(largest);
  const int shift = fixed_point_shift(largest);
  return fixed_point_wrms(fixed_point_squares(x, w, n, shift), shift, static_cast<double>(n));
}

void use_fixed_point_norm(N_Vector v) {
  const N_Vector_ID id = N_VGetVectorID(v);
  if (id != SUNDIALS_NVEC_SERIAL && id != SUNDIALS_NVEC_OPENMP)
    throw std::invalid_argument("use_fixed_point_norm: a serial or OpenMP vector is needed");
  v->ops->nvwrmsnorm = &wrms_op;
}

}  // namespace sphmol
