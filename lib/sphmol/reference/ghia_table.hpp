#pragma once
// Lid-driven cavity centre-line reference of Ghia, Ghia & Shin (1982), J. Comput. Phys. 48:387, Tables I
// and II, as stored in verification/ghia1982_*.csv (see verification/README.md).
// File format: a header "y [-],u_Re100 [-],u_Re400 [-],..." (resp. "x [-],v_Re100 [-],..."; the unit is
// optional and must be "[-]": the table is dimensionless), then rows of numbers with the coordinate
// strictly increasing in [0, 1]. Lines starting with '#' are skipped.
#include <optional>
#include <string>
#include <vector>

namespace sphmol {

struct GhiaTable {
  double Re = 0.0;
  std::vector<double> y, u;  // u(x = 0.5, y), vertical centre line
  std::vector<double> x, v;  // v(x, y = 0.5), horizontal centre line
};

// Centre-line data for the column whose Re matches within 1e-9 relative; std::nullopt when neither file
// has that Re (the caller then runs without comparison). Throws std::runtime_error naming file and line for
// a missing or malformed file, or when only one of the two files has the Re.
std::optional<GhiaTable> load_ghia(const std::string& path_u, const std::string& path_v, double Re);

}  // namespace sphmol
