#include "sphmol/analysis/hexagonal_lattice.hpp"

#include <cmath>

namespace sphmol::analysis {

std::vector<std::array<double, 2>> hexagonal_lattice_points(double d, double radius) {
  std::vector<std::array<double, 2>> pts;
  const double s3 = std::sqrt(3.0) / 2.0;
  const int nb = int(std::ceil(radius / (s3 * d))) + 1;
  for (int b = -nb; b <= nb; ++b) {
    const int na = int(std::ceil(radius / d)) + nb + 1;
    for (int a = -na; a <= na; ++a) {
      const double x = (a + 0.5 * b) * d, y = b * s3 * d;
      if (x * x + y * y <= radius * radius * (1.0 + 1e-14)) pts.push_back({x, y});
    }
  }
  return pts;
}

}  // namespace sphmol::analysis
