#pragma once
// The least-squares slope of y against x, the one line fit that the convergence studies (the order of
// log error against log step) and the decaying cases (the rate of log amplitude against time) read.
#include <cstddef>
#include <limits>
#include <vector>

namespace sphmol {

// (n Σxy − Σx Σy) / (n Σx² − (Σx)²) over the pairs (x[k], y[k]); NaN for fewer than two points.
inline double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t count = x.size() < y.size() ? x.size() : y.size();
  if (count < 2) return std::numeric_limits<double>::quiet_NaN();
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < count; ++k) {
    sx += x[k];
    sy += y[k];
    sxx += x[k] * x[k];
    sxy += x[k] * y[k];
  }
  const double n = static_cast<double>(count);
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace sphmol
