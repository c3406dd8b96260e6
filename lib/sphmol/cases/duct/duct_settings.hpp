#pragma once
// The `geometry` keys of the duct case: the cross-section's half-widths and the periodic length.
#include <string>

#include "sphmol/config/config.hpp"

namespace sphmol {

struct DuctSettings final : CaseSettings {
  double half_width_y = 0.0;  // a [m]: the walls are at y = -a and a
  double half_width_z = 0.0;  // b [m]: the walls are at z = -b and b
  double length = 0.0;        // periodic length along x [m]
  std::string to_yaml() const override;
};

}  // namespace sphmol
