// Checkpoint doubles as hex: bit-exact round trip including -0, subnormals, inf and NaN payloads.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>

#include "sphmol/io/double_codec.hpp"

using namespace sphmol;

TEST_CASE("double codec: bit-exact round trip", "[io][checkpoint]") {
  const std::vector<double> v = {0.0, -0.0, 1.0, 0.1, -1e-310, std::numeric_limits<double>::max(),
                                 std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN(),
                                 3.141592653589793};
  const std::string hex = encode_doubles(v);
  REQUIRE(hex.size() == 16 * v.size());
  CHECK(hex.substr(16 * 2, 16) == "3ff0000000000000");  // 1.0, most significant nibble first
  const std::vector<double> back = decode_doubles(hex);
  REQUIRE(back.size() == v.size());
  CHECK(std::memcmp(back.data(), v.data(), v.size() * sizeof(double)) == 0);
}

TEST_CASE("double codec: malformed text is rejected", "[io][checkpoint]") {
  CHECK_THROWS_WITH(decode_doubles("3ff000000000000"), Catch::Matchers::Contains("multiple of 16"));
  CHECK_THROWS_WITH(decode_doubles("3ff000000000000g"), Catch::Matchers::Contains("invalid hex"));
  CHECK(decode_doubles("").empty());
}
