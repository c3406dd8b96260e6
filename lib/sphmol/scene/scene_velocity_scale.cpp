#include "sphmol/scene/scene_velocity_scale.hpp"

namespace sphmol {

template <int D>
double scene_velocity_scale(const Particles<D>& p, const std::vector<double>& body_force, double spacing) {
  VelocityScaleSums<D> sums(body_force);
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::array<double, D> x{}, v{};
    for (int d = 0; d < D; ++d) x[d] = p.x[d][i], v[d] = p.v[d][i];
    sums.add(x, v, p.kind[i] == Kind::Fluid);
  }
  return sums.value(p.n_fluid, spacing);
}

template double scene_velocity_scale<2>(const Particles<2>&, const std::vector<double>&, double);
template double scene_velocity_scale<3>(const Particles<3>&, const std::vector<double>&, double);

}  // namespace sphmol
