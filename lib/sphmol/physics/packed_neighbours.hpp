#pragma once
// The neighbour data of the weakly compressible row (physics/weakly_compressible_row.hpp) packed per
// particle: position, velocity, density, p/rho^2, sound speed and (fluid) m/rho in one record, which
// in 2D is 8 doubles, one 64-byte cache line. A pair's gathers of particle j then touch one line
// instead of one line in each of eight arrays, and in 2D four pairs' records load as eight 256-bit
// vectors and transpose in registers into the contiguous per-pair arrays the row's arithmetic runs
// over (gather_neighbours), instead of 32 scalar loads and stores. The numbers are copies: a row
// reading them computes exactly what it computes from the arrays they were copied from.
#include <cstddef>
#include <cstdint>

#if defined(__AVX__)
#include <immintrin.h>
#endif

namespace sphmol {

template <int D>
struct alignas((2 * D + 4) * sizeof(double) == 64 ? 64 : alignof(double)) PackedNeighbour {
  double x[D], v[D], rho, q, c, vol;  // q = p / rho^2; vol = m / rho for fluid particles, 0 for walls
};

// Structure of arrays of one block of at most N pairs' neighbour data.
template <int D, std::uint32_t N>
struct NeighbourBlock {
  static_assert(N % 4 == 0, "a block holds whole groups of four lanes");
  alignas(32) double x[D][N];
  alignas(32) double v[D][N];
  alignas(32) double rho[N];
  alignas(32) double q[N];
  alignas(32) double c[N];
  alignas(32) double vol[N];
};

#if defined(__AVX__)
// 4x4 transpose of four 256-bit rows: lane l of f[k] is lane k of row a_l (the rows of four pairs'
// records into four per-field vectors, or back). Shuffles only: the numbers are unchanged.
inline void transpose4(__m256d a0, __m256d a1, __m256d a2, __m256d a3, __m256d& f0, __m256d& f1, __m256d& f2, __m256d& f3) {
  const __m256d t0 = _mm256_unpacklo_pd(a0, a1), t1 = _mm256_unpackhi_pd(a0, a1);
  const __m256d t2 = _mm256_unpacklo_pd(a2, a3), t3 = _mm256_unpackhi_pd(a2, a3);
  f0 = _mm256_permute2f128_pd(t0, t2, 0x20);
  f1 = _mm256_permute2f128_pd(t1, t3, 0x20);
  f2 = _mm256_permute2f128_pd(t0, t2, 0x31);
  f3 = _mm256_permute2f128_pd(t1, t3, 0x31);
}
#endif

// Lanes a gather fills for n pairs: n rounded up to a multiple of 4.
constexpr std::uint32_t gathered_lanes(std::uint32_t n) { return (n + 3u) & ~3u; }

// Lanes k < n of `out` from pk[j[k]]; lanes n .. gathered_lanes(n) repeat pair n - 1 (n > 0), so that
// loops over whole groups of four read finite numbers there. n <= N.
template <int D, std::uint32_t N>
void gather_neighbours(const PackedNeighbour<D>* pk, const std::uint32_t* j, std::uint32_t n, NeighbourBlock<D, N>& out) {
  const std::uint32_t lanes = gathered_lanes(n);
#if defined(__AVX__)
  if constexpr (D == 2 && sizeof(PackedNeighbour<D>) == 64) {
    // Each record is two rows of four, (x0 x1 v0 v1) and (rho q c vol); a 4x4 transpose of four pairs'
    // rows gives each field's four lanes.
    const auto group = [&out](std::uint32_t k, const double* p0, const double* p1, const double* p2, const double* p3) {
      for (int half = 0; half < 2; ++half) {
        __m256d f[4];
        transpose4(_mm256_load_pd(p0 + 4 * half), _mm256_load_pd(p1 + 4 * half), _mm256_load_pd(p2 + 4 * half),
                   _mm256_load_pd(p3 + 4 * half), f[0], f[1], f[2], f[3]);
        _mm256_store_pd((half == 0 ? out.x[0] : out.rho) + k, f[0]);
        _mm256_store_pd((half == 0 ? out.x[1] : out.q) + k, f[1]);
        _mm256_store_pd((half == 0 ? out.v[0] : out.c) + k, f[2]);
        _mm256_store_pd((half == 0 ? out.v[1] : out.vol) + k, f[3]);
      }
    };
    const double* base = &pk[0].x[0];
    constexpr std::size_t stride = sizeof(PackedNeighbour<D>) / sizeof(double);
    std::uint32_t k = 0;
    for (; k + 4 <= n; k += 4)
      group(k, base + j[k] * stride, base + j[k + 1] * stride, base + j[k + 2] * stride, base + j[k + 3] * stride);
    if (k < n) {
      const std::uint32_t last = n - 1;
      group(k, base + j[k] * stride, base + j[k + 1 < n ? k + 1 : last] * stride, base + j[k + 2 < n ? k + 2 : last] * stride,
            base + j[last] * stride);
    }
    return;
  }
#endif
  for (std::uint32_t k = 0; k < lanes; ++k) {
    const PackedNeighbour<D>& p = pk[j[k < n ? k : n - 1]];
    for (int d = 0; d < D; ++d) {
      out.x[d][k] = p.x[d];
      out.v[d][k] = p.v[d];
    }
    out.rho[k] = p.rho;
    out.q[k] = p.q;
    out.c[k] = p.c;
    out.vol[k] = p.vol;
  }
}

}  // namespace sphmol
