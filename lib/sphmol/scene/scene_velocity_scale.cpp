#include "sphmol/scene/scene_velocity_scale.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sphmol {

template <int D>
double scene_velocity_scale(const Particles<D>& p, const std::vector<double>& body_force, double spacing) {
  double g2 = 0.0;
  for (int d = 0; d < D && d < static_cast<int>(body_force.size()); ++d) g2 += body_force[d] * body_force[d];
  const double g = std::sqrt(g2);
  double smin = std::numeric_limits<double>::infinity(), smax = -smin, vmax = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    double v2 = 0.0, s = 0.0;
    for (int d = 0; d < D; ++d) {
      v2 += p.v[d][i] * p.v[d][i];
      if (g > 0.0) s -= p.x[d][i] * body_force[d] / g;
    }
    vmax = std::max(vmax, std::sqrt(v2));
    if (p.kind[i] == Kind::Fluid) smin = std::min(smin, s), smax = std::max(smax, s);
  }
  // The height the fluid stands for: the span of its particles plus half a spacing at each end.
  const double H = p.n_fluid > 0 ? smax - smin + spacing : 0.0;
  return std::max(vmax, g > 0.0 ? std::sqrt(2.0 * g * H) : 0.0);
}

template double scene_velocity_scale<2>(const Particles<2>&, const std::vector<double>&, double);
template double scene_velocity_scale<3>(const Particles<3>&, const std::vector<double>&, double);

}  // namespace sphmol
