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

ChannelErrors channel_errors(const SphSystem<2>& sys, const double* y, double t, const ChannelReference& ref) {
  const auto& L = sys.layout();
  ChannelErrors e;
  e.t = t;
  e.profile.reserve(L.n);
  double sum2 = 0.0;
  for (std::size_t i = 0; i < L.n; ++i) {
    const double yi = y[L.position(1) + i];
    const double u = y[L.velocity(0) + i];
    const double ue = ref.velocity(yi, t);
    const double err = std::abs(u - ue) / ref.v0;
    sum2 += err * err;
    e.e_max = std::max(e.e_max, err);
    e.profile.push_back({yi, u, ue});
  }
  e.e_rms = std::sqrt(sum2 / static_cast<double>(L.n));
  std::sort(e.profile.begin(), e.profile.end(), [](const auto& a, const auto& b) { return a.y < b.y; });
  return e;
}

}  // namespace sphmol
