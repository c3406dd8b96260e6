#pragma once
// The `geometry` keys of the Taylor-Green case: the periodic square and the vortex amplitude.
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol {

struct TaylorGreenSettings final : CaseSettings {
  std::vector<double> box;          // [L, L] [m]
  double velocity_amplitude = 1.0;  // U [m/s], > 0
  std::string to_yaml() const override;
};

}  // namespace sphmol
