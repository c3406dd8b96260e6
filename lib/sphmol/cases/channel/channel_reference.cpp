#include "sphmol/cases/channel/channel_reference.hpp"
#include "sphmol/cases/channel/channel_settings.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "sphmol/reference/couette_series.hpp"
#include "sphmol/reference/poiseuille_series.hpp"
#include "sphmol/reference/ramped_start.hpp"

namespace sphmol {

ChannelReference make_channel_reference(const Config& config) {
  const auto& s = config.settings<ChannelSettings>();
  const double l = s.channel_height, nu = config.fluid.kinematic_viscosity;
  const double F = config.fluid.body_force.empty() ? 0.0 : config.fluid.body_force[0];
  const double ramp = config.fluid.body_force_ramp;
  // The problem is linear with the same walls: the moving plate's series and the body force's series add.
  std::optional<CouetteSeries> plate;
  if (s.wall_velocity != 0.0) plate = CouetteSeries{l, nu, s.wall_velocity};
  std::optional<PoiseuilleSeries> force;
  if (F != 0.0) force = PoiseuilleSeries{l, nu, F};
  ChannelReference ref;
  ref.v0 = s.couette ? s.wall_velocity : force->peak_velocity();
  // The quadrature of a ramped force to 1e-14 of the flow's speed scale, below the series' own accuracy.
  const double tol = 1e-14 * std::abs(ref.v0);
  ref.velocity = [plate, force, ramp, tol](double y, double t) {
    double u = plate ? plate->velocity(y, t) : 0.0;
    if (force) u += ramped_start([&](double tau) { return force->velocity(y, tau); }, t, ramp, tol);
    return u;
  };
  if (plate) ref.name = "Couette start-up series (Vukčević et al. 2012, eq 23)";
  if (force) {
    ref.name += std::string(plate ? " plus the " : "") + "Poiseuille start-up series (Vukčević et al. 2012, eq 19)";
    if (ramp > 0.0) ref.name += " of the body force ramped in over fluid.body_force_ramp (Duhamel's principle)";
  }
  return ref;
}

}  // namespace sphmol
