#include "sphmol/rhs/assemble.hpp"

#include <stdexcept>

#include "sphmol/boundary/morris_wall_velocity.hpp"
#include "sphmol/physics/body_force.hpp"
#include "sphmol/physics/eos_linear.hpp"
#include "sphmol/physics/morris_viscosity.hpp"
#include "sphmol/physics/pressure_gradient.hpp"
#include "sphmol/physics/strain_rate.hpp"
#include "sphmol/physics/strain_rate_viscosity.hpp"
#include "sphmol/physics/summation_density.hpp"
#include "sphmol/physics/xsph.hpp"

namespace sphmol {

template <int D>
std::unique_ptr<SphSystem<D>> assemble_system(const Config& config, Particles<D> particles, const Domain<D>& domain,
                                              double spacing) {
  const auto& disc = config.discretization;
  const auto& fluid = config.fluid;
  const double h = disc.smoothing_ratio * spacing;
  auto kernel = make_kernel_pass<D>(disc.kernel);
  const double mu = fluid.density * fluid.kinematic_viscosity;

  std::vector<std::unique_ptr<Term<D>>> terms;
  if (disc.density != "summation") throw std::invalid_argument("discretization.density: unsupported '" + disc.density + "'");
  terms.push_back(std::make_unique<SummationDensity<D>>());
  if (fluid.eos.type != "linear" && fluid.eos.type != "linear_relative")
    throw std::invalid_argument("fluid.eos.type: unsupported '" + fluid.eos.type + "'");
  terms.push_back(std::make_unique<LinearEos<D>>(fluid.eos.sound_speed, fluid.density, fluid.eos.type == "linear_relative"));
  if (disc.momentum != "symmetric_117") throw std::invalid_argument("discretization.momentum: unsupported '" + disc.momentum + "'");
  if (disc.wall_model == "morris") terms.push_back(std::make_unique<MorrisWallVelocity<D>>(disc.wall_beta_max));
  else if (disc.wall_model != "prescribed")
    throw std::invalid_argument("discretization.wall_model: unsupported '" + disc.wall_model + "'");
  if (disc.viscosity == "strain_rate") {
    terms.push_back(std::make_unique<StrainRate<D>>());
    terms.push_back(std::make_unique<PressureGradient117<D>>());
    terms.push_back(std::make_unique<StrainRateViscosity117<D>>(mu));
  } else if (disc.viscosity == "morris") {
    terms.push_back(std::make_unique<PressureGradient117<D>>());
    terms.push_back(std::make_unique<MorrisViscosity<D>>(mu));
  } else {
    throw std::invalid_argument("discretization.viscosity: unsupported '" + disc.viscosity + "'");
  }
  std::array<double, D> g{};
  bool any_force = false;
  for (int d = 0; d < D && d < static_cast<int>(fluid.body_force.size()); ++d) {
    g[d] = fluid.body_force[d];
    any_force = any_force || g[d] != 0.0;
  }
  if (any_force) terms.push_back(std::make_unique<BodyForce<D>>(g));
  if (disc.xsph > 0.0) terms.push_back(std::make_unique<Xsph<D>>(disc.xsph));

  auto list = std::make_unique<VerletList<D>>(make_neighbor_search<D>(disc.neighbor_search), kernel->support() * h,
                                              disc.skin * h);
  CflLimits cfl{config.time.cfl.acoustic, config.time.cfl.force, config.time.cfl.viscous, fluid.eos.sound_speed,
                fluid.kinematic_viscosity};
  return std::make_unique<SphSystem<D>>(std::move(particles), domain, h, std::move(kernel), std::move(terms),
                                        std::move(list), cfl);
}

template std::unique_ptr<SphSystem<1>> assemble_system<1>(const Config&, Particles<1>, const Domain<1>&, double);
template std::unique_ptr<SphSystem<2>> assemble_system<2>(const Config&, Particles<2>, const Domain<2>&, double);
template std::unique_ptr<SphSystem<3>> assemble_system<3>(const Config&, Particles<3>, const Domain<3>&, double);

}  // namespace sphmol
