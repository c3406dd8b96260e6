#pragma once
// The `geometry` keys of the dam break: the tank and the water column at its left end.
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol {

struct DamBreakSettings final : CaseSettings {
  std::vector<double> box;     // the tank [Lx, Ly] [m]
  std::vector<double> column;  // the water column [width, height] at x = 0 [m]
  std::string to_yaml() const override;
};

}  // namespace sphmol
