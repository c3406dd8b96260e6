#pragma once
// The keys of the shock tube: the tube (`geometry`) and the two initial states (`shock_tube`),
// left for x < 0 and right for x >= 0 (Niedoba 2012, §3.2).
#include <string>

#include "sphmol/config/config.hpp"

namespace sphmol {

struct ShockTubeState {
  double density = 0.0, pressure = 0.0, velocity = 0.0;
};

struct ShockTubeSettings final : CaseSettings {
  int dimension = 1;
  double tube_length = 0.0;  // fluid extent in x, centred on the diaphragm at x = 0 [m], > 0
  double tube_width = 0.0;   // extent in y (2D, periodic or walled) [m], > 0
  ShockTubeState left, right;
  std::string to_yaml() const override;
};

}  // namespace sphmol
