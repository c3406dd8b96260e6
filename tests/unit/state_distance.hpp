#pragma once
// RMS distance between two states of equal length: the error measure of the integrator order tests.
#include <cmath>
#include <vector>

inline double rms_distance(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(s / static_cast<double>(a.size()));
}
