// output.vtk, output.vtk_walls, output.plots, output.checkpoint_every: defaults, values, errors with
// file:line and the to_yaml round trip.
#include <catch2/catch.hpp>

#include "config_test_base.hpp"
#include "sphmol/config/config.hpp"

using namespace sphmol;
using config_test::base;
using config_test::error_of;
using config_test::with;
using Catch::Matchers::Contains;

TEST_CASE("output keys: defaults are off", "[config][output]") {
  const Config c = load_config_string(base);
  CHECK_FALSE(c.output.vtk);
  CHECK(c.output.vtk_walls);
  CHECK_FALSE(c.output.plots);
  CHECK(c.output.checkpoint_every == 0.0);
}

TEST_CASE("output keys: values are read and survive to_yaml", "[config][output]") {
  const std::string yaml = with("  times: [0.1, 0.2]\n",
                                "  times: [0.1, 0.2]\n  vtk: true\n  vtk_walls: false\n  plots: yes\n"
                                "  checkpoint_every: 0.125\n");
  const Config c = load_config_string(yaml);
  CHECK(c.output.vtk);
  CHECK_FALSE(c.output.vtk_walls);
  CHECK(c.output.plots);
  CHECK(c.output.checkpoint_every == 0.125);
  const Config r = load_config_string(to_yaml(c));
  CHECK(r.output.vtk == c.output.vtk);
  CHECK(r.output.vtk_walls == c.output.vtk_walls);
  CHECK(r.output.plots == c.output.plots);
  CHECK(r.output.checkpoint_every == c.output.checkpoint_every);
  CHECK(to_yaml(r) == to_yaml(c));
}

TEST_CASE("output keys: errors name file, line, key and the allowed values", "[config][output]") {
  CHECK_THAT(error_of(with("  times: [0.1, 0.2]\n", "  times: [0.1, 0.2]\n  checkpoint_every: -1\n")),
             Contains("case.yaml:18: output.checkpoint_every: -1 is out of range (allowed: >= 0 s"));
  CHECK_THAT(error_of(with("  times: [0.1, 0.2]\n", "  times: [0.1, 0.2]\n  vtk: 3\n")),
             Contains("case.yaml:18: output.vtk:"));
  CHECK_THAT(error_of(with("  times: [0.1, 0.2]\n", "  times: [0.1, 0.2]\n  plot: true\n")),
             Contains("case.yaml:18: output.plot: unknown key"));
  CHECK_THAT(error_of(base, {"output.checkpoint_every=abc"}), Contains("--set output.checkpoint_every=abc"));
}

TEST_CASE("output keys: vtk_ghosts needs ghost walls and vtk", "[config][output][ghost]") {
  CHECK_FALSE(load_config_string(base).output.vtk_ghosts);
  CHECK_THAT(error_of(with("  times: [0.1, 0.2]\n", "  times: [0.1, 0.2]\n  vtk: true\n  vtk_ghosts: true\n")),
             Contains("output.vtk_ghosts: needs discretization.boundary: ghost"));
}
