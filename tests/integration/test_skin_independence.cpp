// The Verlet skin changes how often the neighbour list is rebuilt and how many skin pairs (beyond the
// kernel support, W = F = 0) each row carries, but not the result: rows are sorted by neighbour index
// whatever the list radius, and a skin pair adds exact zeros to every sum of the weakly compressible
// row. So the dam break's state is the same bit for bit at any skin, which lets the dam break ship
// the skin that is cheapest per step (docs/performance.md).
#include <catch2/catch.hpp>

#include <string>

#include "sphmol/config/config.hpp"
#include "support/stepped_run.hpp"

using namespace sphmol;

namespace {

using test_support::differing;
using Run = test_support::SteppedRun;

Run run_dam_break(const std::string& skin, int steps, int threads) {
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml",
                               {"discretization.spacing=0.04", "time.t_end=1.0", "discretization.skin=" + skin});
  return test_support::run_steps<2>(c, steps, threads, [](auto&) {});
}

}  // namespace

TEST_CASE("dam break: the state is the same bit for bit at any Verlet skin", "[integration][neighbors]") {
  for (int threads : {1, 2}) {
    INFO("threads " << threads);
    const Run wide = run_dam_break("0.3", 300, threads);
    for (const char* skin : {"0.15", "0.05"}) {
      INFO("skin " << skin);
      const Run narrow = run_dam_break(skin, 300, threads);
      CHECK(narrow.rebuilds > wide.rebuilds);  // the lists differed during the run
      REQUIRE(narrow.y.size() == wide.y.size());
      CHECK(differing(narrow.y, wide.y) == 0);
    }
  }
}
