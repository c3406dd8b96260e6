// Units of the cases' error measures in the study CSV headers: the shock tube's L1 norms carry
// their field's unit, every other measure is relative.
#include <catch2/catch.hpp>

#include "sphmol/run/error_unit.hpp"

using sphmol::error_unit;

TEST_CASE("error_unit: L1 norms of the shock tube fields, relative errors dimensionless", "[csv][studies]") {
  CHECK(error_unit("L1_rho") == "kg/m^3");
  CHECK(error_unit("L1_mid_u") == "m/s");
  CHECK(error_unit("L1_p") == "Pa");
  CHECK(error_unit("L1_e") == "J/kg");
  CHECK(error_unit("L1_velocity") == "-");  // Taylor-Green: divided by the exact amplitude
  for (const char* key : {"e_rms", "u_rms", "p_rms", "front_rms_martin_moyce", ""}) CHECK(error_unit(key) == "-");
}
