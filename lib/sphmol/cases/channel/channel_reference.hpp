#pragma once
// The exact start-up solution a channel case is measured against (cases/channel/channel_case.hpp:
// e_rms(t) = sqrt(mean_i (u_i - u_exact(y_i, t))^2) / |v0|, e_max = max_i |...| / |v0|, over fluid
// particles); v0 is the Couette plate speed or the Poiseuille peak speed, signed (negative for a flow
// driven along -x).
#include <functional>
#include <string>

#include "sphmol/config/config.hpp"

namespace sphmol {

struct ChannelReference {
  std::function<double(double y, double t)> velocity;
  double v0 = 0.0;
  std::string name;  // which series
};

ChannelReference make_channel_reference(const Config& config);

}  // namespace sphmol
