#include "sphmol/time/block_error_weights.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sphmol {

void block_error_weights(const StateBlocks& b, double rtol, double atol, const double* y, double* w,
                         const MinimumOverProcesses& minimum) {
  const std::size_t vb = b.velocities_begin, ve = b.velocities_end, L = b.block > 0 ? b.block : vb;
  // Minima of each position block, negated maxima, and the negated largest speed: the same count on
  // every process (a process without fluid has empty blocks: +inf, which no minimum takes).
  constexpr std::size_t kBlocks = 3;
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::array<double, 2 * kBlocks + 1> m;
  m.fill(inf);
  std::size_t p = 0;
  for (std::size_t lo = 0; L > 0 && lo + L <= vb; lo += L, ++p) {
    if (p == kBlocks) throw std::invalid_argument("block_error_weights: more than 3 position blocks");
    const auto [mn, mx] = std::minmax_element(y + lo, y + lo + L);
    m[2 * p] = *mn;
    m[2 * p + 1] = -*mx;
  }
  double speed = 0.0;
  for (std::size_t k = vb; k < ve; ++k) speed = std::max(speed, std::abs(y[k]));
  m[2 * kBlocks] = -speed;
  if (minimum) minimum(m.data(), m.size());
  double extent = 0.0;
  for (std::size_t q = 0; q < kBlocks; ++q)
    if (m[2 * q] < inf) extent = std::max(extent, -m[2 * q + 1] - m[2 * q]);
  speed = -m[2 * kBlocks];
  for (std::size_t k = 0; k < b.size; ++k) {
    const double scale = k < vb ? extent : (k < ve ? speed : 0.0);
    w[k] = 1.0 / (rtol * (std::abs(y[k]) + scale) + atol);
  }
}

}  // namespace sphmol
