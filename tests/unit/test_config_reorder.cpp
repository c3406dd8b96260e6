// discretization.reorder: default, parsing, round trip through to_yaml, and the ghost combination error.
#include <catch2/catch.hpp>

#include <string>

#include "sphmol/config/config.hpp"

using namespace sphmol;
using Catch::Matchers::Contains;

namespace {
const std::string cavity = std::string(SPHMOL_SOURCE_DIR) + "/verification/cavity.yaml";
}

TEST_CASE("config: discretization.reorder defaults to false and parses", "[config]") {
  CHECK_FALSE(load_config(cavity).discretization.reorder);
  const Config on = load_config(cavity, {"discretization.reorder=true"});
  CHECK(on.discretization.reorder);
  CHECK(to_yaml(on).find("reorder: true") != std::string::npos);
}

TEST_CASE("config: discretization.reorder is rejected with ghost particles, naming the key", "[config]") {
  std::string msg = "<no error>";
  try {
    load_config(cavity, {"discretization.boundary=ghost", "discretization.wall_model=prescribed", "discretization.reorder=true"});
  } catch (const std::exception& e) {
    msg = e.what();
  }
  CHECK_THAT(msg, Contains("discretization.reorder") && Contains("ghost"));
}
