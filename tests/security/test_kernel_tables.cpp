// `sph-mol kernels --analysis hydrostatic --output DIR` writes its CSV tables through fresh
// temporaries: a link planted at a table's name is replaced, never followed into its target.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/process.hpp"

namespace fs = std::filesystem;

TEST_CASE("kernels: a link planted at a table's name is replaced, its target untouched", "[security][io][csv]") {
  const fs::path dir = fs::temp_directory_path() / ("sphmol-sec-" + std::to_string(::getpid()) + "-kernels");
  fs::remove_all(dir);
  fs::create_directories(dir / "out");
  const fs::path victim = dir / "victim.txt";
  { std::ofstream(victim) << "precious"; }
  fs::create_symlink(victim, dir / "out" / "hydrostatic_table.csv");
  fs::create_symlink(victim, dir / "out" / "hydrostatic_curves_cubic_spline.csv");
  const auto r = test_support::run_process(
      SPHMOL_BINARY, {"kernels", "--analysis", "hydrostatic", "--kernel", "cubic_spline", "--output", (dir / "out").string()},
      (dir / "err").string());
  INFO(r.err);
  REQUIRE(r.code == 0);
  std::ifstream in(victim);
  std::ostringstream s;
  s << in.rdbuf();
  CHECK(s.str() == "precious");
  for (const char* f : {"hydrostatic_table.csv", "hydrostatic_curves_cubic_spline.csv"}) {
    CHECK_FALSE(fs::is_symlink(dir / "out" / f));
    CHECK(fs::file_size(dir / "out" / f) > 100);
  }
  fs::remove_all(dir);
}
