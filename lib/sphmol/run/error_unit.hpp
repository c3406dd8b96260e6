#pragma once
// The unit of a case's error measure (the keys of summary.json "final_errors"), for column names
// of the study CSV files: the shock tube's L1 norms carry the unit of their field; every other
// error measure is relative (divided by a reference speed, pressure or length).
#include <string>
#include <string_view>

namespace sphmol {

inline std::string error_unit(std::string_view key) {
  if (key.starts_with("L1_") && !key.starts_with("L1_velocity")) {
    const std::string_view field = key.substr(key.rfind('_') + 1);
    if (field == "rho") return "kg/m^3";
    if (field == "u") return "m/s";
    if (field == "p") return "Pa";
    if (field == "e") return "J/kg";
  }
  return "-";
}

}  // namespace sphmol
