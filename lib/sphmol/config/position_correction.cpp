// The cell-Reynolds-number rule of discretization.position_correction: auto.
#include "sphmol/config/position_correction.hpp"

#include <limits>

namespace sphmol {

double cell_reynolds_number(double velocity_scale, double smoothing_length, double kinematic_viscosity) {
  if (!(kinematic_viscosity > 0.0)) return std::numeric_limits<double>::infinity();
  return velocity_scale * smoothing_length / kinematic_viscosity;
}

std::string position_correction_for(double cell_reynolds) {
  return cell_reynolds < kPositionCorrectionCellReynolds ? "transport_velocity" : "particle_shifting";
}

}  // namespace sphmol
