#pragma once
// The `geometry` keys of the hydrostatic tank: the water column.
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol {

struct HydrostaticSettings final : CaseSettings {
  std::vector<double> box;  // [width, depth] (3D: [width, breadth, depth]) of the water column [m]
  std::string to_yaml() const override;
};

}  // namespace sphmol
