#pragma once
// How long the shock tube may run: it is measured against the exact Riemann solution of an infinite
// tube, which the tube of finite length follows only while the gas that the end walls' particles
// reach is still in its initial state. The outermost waves run into that gas at the speeds of Toro
// (2009) eqs 4.52, 4.55 (left: shock, fan head) and 4.59, 4.62 (right).
#include <array>

#include "sphmol/reference/exact_riemann.hpp"

namespace sphmol {

struct ShockTubeClearance {
  double t_clear;  // the latest time the outermost waves are still outside both end walls' reach [s]
  int side;        // the end they reach first: 0 left, 1 right
  double speed;    // the speed of that wave towards its end [m/s], > 0
  bool shock;      // that wave is a shock (else the head of a fan)
};

// half_length: from the diaphragm to each end wall [m]; reach[side]: the distance from that end
// wall within which the gas interacts with the wall particles [m]. The states must be at rest (a
// moving state disturbs its end wall from t = 0). t_clear <= 0 when an end's reach covers its half.
ShockTubeClearance shock_tube_clearance(const ExactRiemannSolver& exact, double half_length, const std::array<double, 2>& reach);

// The shortest tube (centred on the diaphragm) that keeps the waves clear of the walls until t [m].
double shock_tube_length_for(const ExactRiemannSolver& exact, double t, const std::array<double, 2>& reach);

}  // namespace sphmol
