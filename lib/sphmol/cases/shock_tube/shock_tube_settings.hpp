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
  // Particle setup (shock_tube_scene.hpp): equal_mass (the spacing of the lighter side scaled by
  // (rho_dense / rho_light)^(1/D), Price 2008 / Monaghan 1997) or equal_spacing (Niedoba 2012, §3.2:
  // one lattice, the masses carry the jump).
  std::string setup = "equal_mass";
  // Width of the smoothed initial discontinuity in spacings of the denser side; 0 = a sharp jump.
  double smoothing = 0.0;
  std::string to_yaml() const override;
};

}  // namespace sphmol
