#pragma once
// The `geometry` keys of the Couette and Poiseuille cases: the channel between two plates.
#include <string>

#include "sphmol/config/config.hpp"

namespace sphmol {

struct ChannelSettings final : CaseSettings {
  bool couette = true;          // false: Poiseuille (body-force driven)
  double channel_height = 0.0;  // l [m], > 0
  double channel_length = 0.0;  // periodic length in x [m], > 0
  double wall_velocity = 0.0;   // Couette top-plate speed v0 [m/s]; 0 for Poiseuille
  std::string to_yaml() const override;
};

}  // namespace sphmol
