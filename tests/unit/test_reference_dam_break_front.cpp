// The dam-break experiments apply to the column H = 2a only, to a relative 1e-6 (reference/dam_break_front.hpp).
#include <catch2/catch.hpp>

#include "sphmol/reference/dam_break_front.hpp"

using namespace sphmol;

TEST_CASE("dam break front: the experiments apply to H = 2a to a relative 1e-6", "[reference][dam_break]") {
  CHECK(experiments_apply(1.0, 2.0));
  CHECK(experiments_apply(0.146, 0.292));
  CHECK(experiments_apply(1.0, 2.0 * (1.0 + 5e-7)));
  CHECK_FALSE(experiments_apply(1.0, 2.0 * (1.0 + 1e-5)));
  CHECK_FALSE(experiments_apply(1.0, 1.0));
  CHECK_FALSE(experiments_apply(2.0, 1.0));
  // Empty data: no front to interpolate.
  CHECK_FALSE(interpolate_front({}, 0.5).has_value());
}
