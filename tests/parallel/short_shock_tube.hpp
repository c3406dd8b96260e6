#pragma once
// A shipped shock tube (verification/) shortened to t = 0.02 s, outputs at 0.01 and 0.02 s and no
// plots, with further settings: the scenes of the tests with the energy equation and variable h.
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

inline sphmol::Config short_shock_tube(const std::string& file, const std::vector<std::string>& more = {}) {
  std::vector<std::string> o{"time.t_end=0.02", "output.times=[0.01,0.02]", "output.plots=false"};
  o.insert(o.end(), more.begin(), more.end());
  return sphmol::load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/" + file, o);
}
