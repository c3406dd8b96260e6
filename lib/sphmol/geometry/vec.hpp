#pragma once
// Points and vectors of the geometry kit: plain std::array<double, D>, as the particle arrays use.
#include <array>
#include <cmath>
#include <cstddef>

namespace sphmol::geometry {

template <int D>
using Vec = std::array<double, D>;

// Element-wise arithmetic, templated on std::array's own size type so that the arguments deduce.
template <std::size_t N>
std::array<double, N> operator+(std::array<double, N> a, const std::array<double, N>& b) {
  for (std::size_t d = 0; d < N; ++d) a[d] += b[d];
  return a;
}
template <std::size_t N>
std::array<double, N> operator-(std::array<double, N> a, const std::array<double, N>& b) {
  for (std::size_t d = 0; d < N; ++d) a[d] -= b[d];
  return a;
}
template <std::size_t N>
std::array<double, N> operator*(double s, std::array<double, N> a) {
  for (std::size_t d = 0; d < N; ++d) a[d] *= s;
  return a;
}
template <int D>
double dot(const Vec<D>& a, const Vec<D>& b) {
  double s = 0.0;
  for (int d = 0; d < D; ++d) s += a[d] * b[d];
  return s;
}
template <int D>
double norm(const Vec<D>& a) {
  return std::sqrt(dot<D>(a, a));
}

// An axis-aligned bounding box; empty when lo > hi in some direction.
template <int D>
struct Bounds {
  Vec<D> lo{}, hi{};
  bool contains(const Vec<D>& p) const {
    for (int d = 0; d < D; ++d)
      if (p[d] < lo[d] || p[d] > hi[d]) return false;
    return true;
  }
  Bounds grown(double by) const {
    Bounds b = *this;
    for (int d = 0; d < D; ++d) {
      b.lo[d] -= by;
      b.hi[d] += by;
    }
    return b;
  }
};

}  // namespace sphmol::geometry
