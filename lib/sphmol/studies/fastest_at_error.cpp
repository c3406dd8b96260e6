#include "sphmol/studies/fastest_at_error.hpp"

#include <cmath>

namespace sphmol {

std::optional<CostAtError> cost_at_error(const std::vector<CurvePoint>& points, double target) {
  const CurvePoint* above = nullptr;  // the latest valid point with error > target
  for (std::size_t i = 0; i < points.size(); ++i) {
    const CurvePoint& p = points[i];
    if (!(std::isfinite(p.error) && std::isfinite(p.cost) && p.error > 0.0 && p.cost > 0.0)) continue;
    if (p.error > target) {
      above = &p;
      continue;
    }
    if (!above) return CostAtError{p.cost, true, i};
    // log-log linear interpolation between `above` and p.
    const double s = (std::log(target) - std::log(above->error)) / (std::log(p.error) - std::log(above->error));
    const double cost = std::exp(std::log(above->cost) + s * (std::log(p.cost) - std::log(above->cost)));
    return CostAtError{cost, false, i};
  }
  return std::nullopt;
}

}  // namespace sphmol
