#pragma once
// "Fastest integrator at a target error" for sph-mol compare. Each integrator's runs form a curve of
// error against cost (wall time, and RHS evaluations), in the order of its sweep (coarse to fine).
// The cost at which the curve first reaches the target is interpolated linearly in log(error) vs
// log(cost) between the last run above the target and the first run at or below it. If the cheapest
// run is already below the target, its cost is an upper bound (`bound: true`) — nothing cheaper was
// run. If no run reaches it, the integrator has no cost at that target. The fastest integrator is the
// one with the smallest interpolated wall time.
#include <optional>
#include <string>
#include <vector>

namespace sphmol {

struct CurvePoint {
  double cost = 0.0;   // wall seconds or RHS evaluations
  double error = 0.0;  // +inf or NaN for a failed run (skipped)
};

struct CostAtError {
  double cost = 0.0;
  bool bound = false;  // the cheapest run already met the target: cost is an upper bound
  std::size_t below = 0;  // index of the first point at or below the target
};

// The interpolated cost at which the curve (points in sweep order) reaches `target`; nullopt if it
// never does. Points with non-finite or non-positive error or cost are skipped.
std::optional<CostAtError> cost_at_error(const std::vector<CurvePoint>& points, double target);

}  // namespace sphmol
