#pragma once
// The velocity scale U of a user scene: the free-fall speed sqrt(2 |g| H) over the fluid's height H
// against the body force, or the largest initial fluid or wall speed, whichever is larger. The
// scene case reports its errors against it; a repulsive wall body takes D = U^2 by default.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "sphmol/core/particles.hpp"

namespace sphmol {

// U accumulated particle by particle, in any order (extremes only), so that a build that keeps only
// part of the scene still finds the whole scene's U.
template <int D>
class VelocityScaleSums {
 public:
  explicit VelocityScaleSums(const std::vector<double>& body_force) : force_(body_force) {
    double g2 = 0.0;
    for (int d = 0; d < D && d < static_cast<int>(force_.size()); ++d) g2 += force_[d] * force_[d];
    g_ = std::sqrt(g2);
  }
  void add(const std::array<double, D>& x, const std::array<double, D>& v, bool fluid) {
    double v2 = 0.0, s = 0.0;
    for (int d = 0; d < D; ++d) {
      v2 += v[d] * v[d];
      if (g_ > 0.0 && d < static_cast<int>(force_.size())) s -= x[d] * force_[d] / g_;
    }
    vmax_ = std::max(vmax_, std::sqrt(v2));
    if (fluid) smin_ = std::min(smin_, s), smax_ = std::max(smax_, s);
  }
  // U of the particles added, `n_fluid` of them fluid, on a lattice of `spacing`.
  double value(std::size_t n_fluid, double spacing) const {
    // The height the fluid stands for: the span of its particles plus half a spacing at each end.
    const double H = n_fluid > 0 ? smax_ - smin_ + spacing : 0.0;
    return std::max(vmax_, g_ > 0.0 ? std::sqrt(2.0 * g_ * H) : 0.0);
  }

 private:
  std::vector<double> force_;
  double g_ = 0.0;
  double smin_ = std::numeric_limits<double>::infinity(), smax_ = -std::numeric_limits<double>::infinity(), vmax_ = 0.0;
};

template <int D>
double scene_velocity_scale(const Particles<D>& p, const std::vector<double>& body_force, double spacing);

}  // namespace sphmol
