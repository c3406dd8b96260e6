#pragma once
// The 2D triangular ("hexagonal", dense-packing) lattice of Potapov & Reshetnikova 2021, sec. 4,
// fig. 2: edge d, rows horizontal (nearest neighbours along x), rows Delta y = sqrt(3)/2 d apart
// (eq 20).
#include <array>
#include <vector>

namespace sphmol::analysis {

// All lattice nodes a*(d, 0) + b*(d/2, sqrt(3)/2 d) within |x| <= radius of the origin node,
// the origin included. Enumerated, so any kernel radius works (no hard-coded neighbour shells).
std::vector<std::array<double, 2>> hexagonal_lattice_points(double d, double radius);

}  // namespace sphmol::analysis
