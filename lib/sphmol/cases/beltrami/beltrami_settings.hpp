#pragma once
// The `geometry` keys of the beltrami case: the periodic cube and the ABC amplitudes.
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"

namespace sphmol {

struct BeltramiSettings final : CaseSettings {
  std::vector<double> box;                        // [L, L, L] [m]
  std::vector<double> amplitudes{1.0, 1.0, 1.0};  // A, B, C [m/s]
  std::string to_yaml() const override;
};

}  // namespace sphmol
