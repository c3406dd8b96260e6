#include "sphmol/cases/channel/channel_reference.hpp"
#include "sphmol/cases/channel/channel_settings.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sphmol/reference/couette_series.hpp"
#include "sphmol/reference/poiseuille_series.hpp"

namespace sphmol {

ChannelReference make_channel_reference(const Config& config) {
  const double l = config.settings<ChannelSettings>().channel_height, nu = config.fluid.kinematic_viscosity;
  ChannelReference ref;
  if (config.settings<ChannelSettings>().couette) {
    CouetteSeries s{l, nu, config.settings<ChannelSettings>().wall_velocity};
    ref.velocity = [s](double y, double t) { return s.velocity(y, t); };
    ref.v0 = config.settings<ChannelSettings>().wall_velocity;
    ref.name = "Couette start-up series (Vukčević et al. 2012, eq 23)";
  } else {
    PoiseuilleSeries s{l, nu, config.fluid.body_force.at(0)};
    ref.velocity = [s](double y, double t) { return s.velocity(y, t); };
    ref.v0 = s.peak_velocity();
    ref.name = "Poiseuille start-up series (Vukčević et al. 2012, eq 19)";
  }
  return ref;
}

}  // namespace sphmol
