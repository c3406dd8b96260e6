// Config keys of the compressible formulations and the shock_tube case: values, the combinations
// that are errors (naming both keys), and the to_yaml round trip.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "sphmol/config/config.hpp"

using namespace sphmol;
using Catch::Matchers::Contains;

namespace {

// SPHMOL_SOURCE_DIR rather than __FILE__: with ccache base_dir, __FILE__ is relative to the build tree.
const std::string shock = std::string(SPHMOL_SOURCE_DIR) + "/verification/shock_tube.yaml";

std::string error_of(const std::vector<std::string>& sets) {
  try {
    (void)load_config(shock, sets);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "<no error>";
}

}  // namespace

TEST_CASE("shock_tube config: values of the shipped file", "[config]") {
  const Config c = load_config(shock);
  CHECK(c.case_name == "shock_tube");
  CHECK(c.fluid.eos.type == "ideal_gas");
  CHECK(c.fluid.eos.gamma == 1.4);
  CHECK(c.shock_tube.left.density == 1.0);
  CHECK(c.shock_tube.right.pressure == 0.1795);
  CHECK(c.geometry.tube_length == 0.8);
  CHECK(c.discretization.density == "continuity");
  CHECK(c.discretization.energy);
  CHECK(c.discretization.smoothing_length == "ode");
  CHECK(c.discretization.artificial_viscosity.enabled);
  CHECK(c.discretization.artificial_viscosity.eta == 0.1);
  const Config r = load_config_string(to_yaml(c));
  CHECK(r.shock_tube.right.density == c.shock_tube.right.density);
  CHECK(r.discretization.artificial_viscosity.alpha == c.discretization.artificial_viscosity.alpha);
  CHECK(r.discretization.smoothing_length == c.discretization.smoothing_length);
  CHECK(r.fluid.eos.gamma == c.fluid.eos.gamma);
  auto body = [](const std::string& y) { return y.substr(y.find('\n')); };  // line 1 names the source
  CHECK(body(to_yaml(r)) == body(to_yaml(c)));
}

TEST_CASE("compressible config: nonsense combinations name both keys", "[config]") {
  CHECK_THAT(error_of({"discretization.energy=false"}),
             Contains("discretization.energy") && Contains("fluid.eos.type 'ideal_gas'"));
  CHECK_THAT(error_of({"discretization.neighbor_search=all_pairs"}),
             Contains("discretization.smoothing_length") && Contains("discretization.neighbor_search: kdtree"));
  CHECK_THAT(error_of({"discretization.density=summation"}),
             Contains("discretization.smoothing_length") && Contains("discretization.density: continuity"));
  CHECK_THAT(error_of({"fluid.kinematic_viscosity=1e-3"}), Contains("discretization.energy") && Contains("kinematic_viscosity"));
  CHECK_THAT(error_of({"fluid.eos.sound_speed=1"}), Contains("fluid.eos.sound_speed") && Contains("ideal_gas"));
  CHECK_THAT(error_of({"fluid.eos.gamma=1"}), Contains("fluid.eos.gamma") && Contains("out of range"));
  CHECK_THAT(error_of({"discretization.artificial_viscosity.eta=0"}), Contains("artificial_viscosity.eta"));
  CHECK_THAT(error_of({"fluid.density=1"}), Contains("fluid.density") && Contains("shock_tube.left.density"));
  CHECK_THAT(error_of({"geometry.channel_height=1"}), Contains("geometry.channel_height"));
  CHECK(error_of({"discretization.smoothing_length=density"}) == "<no error>");  // continuity + 2.67 is fine
  CHECK(error_of({"discretization.smoothing_length=constant", "discretization.neighbor_search=all_pairs"}) == "<no error>");
}
