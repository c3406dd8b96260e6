#pragma once
// The `geometry` keys of the lid-driven cavity: the square and the lid speed.
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol {

struct CavitySettings final : CaseSettings {
  std::vector<double> box;     // [L, L] [m]
  double wall_velocity = 0.0;  // lid speed U [m/s], nonzero
  std::string to_yaml() const override;
};

}  // namespace sphmol
