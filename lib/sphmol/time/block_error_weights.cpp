#include "sphmol/time/block_error_weights.hpp"

#include <algorithm>
#include <cmath>

namespace sphmol {

void block_error_weights(const StateBlocks& b, double rtol, double atol, const double* y, double* w) {
  const std::size_t vb = b.velocities_begin, ve = b.velocities_end, L = b.block > 0 ? b.block : vb;
  double extent = 0.0;
  for (std::size_t lo = 0; L > 0 && lo + L <= vb; lo += L) {
    const auto [mn, mx] = std::minmax_element(y + lo, y + lo + L);
    extent = std::max(extent, *mx - *mn);
  }
  double speed = 0.0;
  for (std::size_t k = vb; k < ve; ++k) speed = std::max(speed, std::abs(y[k]));
  for (std::size_t k = 0; k < b.size; ++k) {
    const double scale = k < vb ? extent : (k < ve ? speed : 0.0);
    w[k] = 1.0 / (rtol * (std::abs(y[k]) + scale) + atol);
  }
}

}  // namespace sphmol
