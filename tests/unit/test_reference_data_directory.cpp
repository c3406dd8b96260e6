// Where the shipped reference tables are looked for: beside an installed binary first (any install
// prefix), then the source tree, then the configured install directory.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "sphmol/reference/data_directory.hpp"

using namespace sphmol;

TEST_CASE("reference data: an installed binary looks in PREFIX/share/sph-mol first", "[reference][install]") {
  const auto dirs = reference_data_dirs("/opt/some prefix/bin/sph-mol");
  REQUIRE(dirs.size() == 3);
  CHECK(dirs[0] == "/opt/some prefix/share/sph-mol");
  CHECK(dirs[1] == std::string(SPHMOL_SOURCE_DIR) + "/verification");
  CHECK(reference_data_dirs("").size() == 2);
}

TEST_CASE("reference data: the Ghia tables are found, a missing file names every place searched",
          "[reference][install]") {
  const std::string u = reference_data_file("ghia1982_u_vertical_centreline.csv");
  CHECK(std::filesystem::is_regular_file(u));
  try {
    (void)reference_data_file("no_such_table.csv");
    FAIL("no error for a missing table");
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    CHECK(msg.find("no_such_table.csv") != std::string::npos);
    CHECK(msg.find(std::string(SPHMOL_SOURCE_DIR) + "/verification") != std::string::npos);
  }
}
