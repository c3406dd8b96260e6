#pragma once
// The exact start-up solution a channel case is measured against, and its error measure
// : e_rms(t) = sqrt(mean_i (u_i - u_exact(y_i, t))^2) / v0, e_max = max_i |...| / v0,
// over fluid particles; v0 is the Couette plate speed or the Poiseuille peak speed.
#include <functional>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/rhs/sph_system.hpp"

namespace sphmol {

struct ChannelReference {
  std::function<double(double y, double t)> velocity;
  double v0 = 0.0;
  std::string name;  // which series
};

ChannelReference make_channel_reference(const Config& config);

struct ProfilePoint {
  double y, u_sph, u_exact;
};

struct ChannelErrors {
  double t = 0.0, e_rms = 0.0, e_max = 0.0;
  std::vector<ProfilePoint> profile;  // sorted by y
};

ChannelErrors channel_errors(const SphSystem<2>& sys, const double* y, double t, const ChannelReference& ref);

}  // namespace sphmol
