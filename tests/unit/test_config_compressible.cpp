// Config keys of the compressible formulations and the shock_tube case: values, the combinations
// that are errors (naming both keys), and the to_yaml round trip.
#include "sphmol/cases/shock_tube/shock_tube_settings.hpp"
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "sphmol/config/config.hpp"

using namespace sphmol;
using Catch::Matchers::Contains;

namespace {

// SPHMOL_SOURCE_DIR, not __FILE__: with CCACHE_BASEDIR the latter is relative to the build directory.
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
  CHECK(c.settings<ShockTubeSettings>().left.density == 1.0);
  CHECK(c.settings<ShockTubeSettings>().right.pressure == 0.1795);
  CHECK(c.settings<ShockTubeSettings>().tube_length == 0.8);
  CHECK(c.discretization.density == "continuity");
  CHECK(c.discretization.energy);
  CHECK(c.discretization.smoothing_length == "ode");
  CHECK(c.discretization.artificial_viscosity.enabled);
  CHECK(c.discretization.artificial_viscosity.eta == 0.1);
  const Config r = load_config_string(to_yaml(c));
  CHECK(r.settings<ShockTubeSettings>().right.density == c.settings<ShockTubeSettings>().right.density);
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
  CHECK_THAT(error_of({"fluid.density=1"}), Contains("fluid.density: is not used by case 'shock_tube' (its initial states give the densities)"));
  CHECK_THAT(error_of({"geometry.channel_height=1"}), Contains("geometry.channel_height"));
  {
    const std::string shock1d = shock.substr(0, shock.size() - 5) + "_1d.yaml";
    std::string e = "<no error>";
    try {
      (void)load_config(shock1d, {"discretization.boundary=ghost"});
    } catch (const ConfigError& x) {
      e = x.what();
    }
    CHECK_THAT(e, Contains("discretization.boundary: the 1D shock tube has no side walls"));
  }
  CHECK(error_of({"discretization.boundary=virtual_repulsive", "discretization.repulsive.strength=1e-3"}) == "<no error>");
  CHECK(error_of({"discretization.boundary=wall_particles"}) == "<no error>");  // y periodic
  CHECK(error_of({"discretization.smoothing_length=density"}) == "<no error>");  // continuity + 2.67 is fine
  CHECK(error_of({"discretization.smoothing_length=constant", "discretization.neighbor_search=all_pairs"}) == "<no error>");
}

TEST_CASE("shock_tube config: setup, smoothing, viscosity form and conductivity keys", "[config]") {
  const std::string sod = std::string(SPHMOL_SOURCE_DIR) + "/verification/sod_1d.yaml";
  const Config c = load_config(sod);
  const auto& st = c.settings<ShockTubeSettings>();
  CHECK(st.setup == "equal_mass");
  CHECK(st.smoothing == 0.25);
  CHECK(c.discretization.artificial_viscosity.form == "monaghan_1997");
  CHECK(c.discretization.artificial_viscosity.beta == 2.0);
  CHECK_FALSE(c.discretization.artificial_conductivity.enabled);
  // Defaults: equal masses across a jump smooth it over a quarter spacing in 1D and one spacing in 2D
  // (sod.yaml); equal spacing keeps it sharp;
  // the signal-velocity form defaults to beta = 2 (Price 2008).
  const Config d = load_config_string(
      "case: shock_tube\ndimension: 1\nfluid: {kinematic_viscosity: 0, eos: {type: ideal_gas, gamma: 1.4}}\n"
      "geometry: {tube_length: 1.0}\nshock_tube: {left: {density: 1, pressure: 1}, right: {density: 0.125, pressure: 0.1}}\n"
      "discretization: {spacing: 0.01, kernel: truncated_exponential, density: continuity, energy: true, "
      "smoothing_length: ode, neighbor_search: kdtree, artificial_viscosity: {form: monaghan_1997}, "
      "artificial_conductivity: {}}\ntime: {t_end: 0.05}\n");  // 6 light particles: the right wall's reach is 0.39 m
  CHECK(d.settings<ShockTubeSettings>().setup == "equal_mass");
  CHECK(d.settings<ShockTubeSettings>().smoothing == 0.25);
  CHECK(d.discretization.artificial_viscosity.beta == 2.0);
  CHECK(d.discretization.artificial_conductivity.enabled);
  CHECK(d.discretization.artificial_conductivity.alpha == 1.0);
  CHECK(load_config(shock).settings<ShockTubeSettings>().smoothing == 0.0);  // equal_spacing
  const Config d2 = load_config_string(
      "case: shock_tube\ndimension: 2\nfluid: {kinematic_viscosity: 0, eos: {type: ideal_gas, gamma: 1.4}}\n"
      "geometry: {tube_length: 1.0, tube_width: 0.05}\nshock_tube: {left: {density: 1, pressure: 1}, right: {density: 0.125, pressure: 0.1}}\n"
      "discretization: {spacing: 0.01, kernel: truncated_exponential, density: continuity, energy: true, "
      "smoothing_length: ode, neighbor_search: kdtree, artificial_viscosity: {form: monaghan_1997}, boundary: ghost}\n"
      "time: {t_end: 0.2}\n");
  CHECK(d2.settings<ShockTubeSettings>().smoothing == 1.0);  // 2D: a sharper jump ejects a light particle
  // Round trip of the new keys.
  const Config r = load_config_string(to_yaml(d));
  CHECK(r.settings<ShockTubeSettings>().smoothing == 0.25);
  CHECK(r.discretization.artificial_viscosity.form == "monaghan_1997");
  CHECK(r.discretization.artificial_conductivity.enabled);
  // Errors.
  CHECK(error_of({"shock_tube.setup=equal_mass"}) == "<no error>");
  CHECK_THAT(error_of({"shock_tube.setup=equal_mass", "discretization.smoothing_length=constant"}),
             Contains("shock_tube.setup: 'equal_mass' with a density jump needs a variable smoothing length"));
  CHECK_THAT(error_of({"shock_tube.setup=equal_mas"}), Contains("shock_tube.setup") && Contains("equal_spacing"));
  CHECK_THAT(error_of({"shock_tube.smoothing=-1"}), Contains("shock_tube.smoothing"));
  CHECK_THAT(error_of({"discretization.artificial_viscosity.form=monaghan_1997"}),
             Contains("discretization.artificial_viscosity.eta") && Contains("monaghan_1992"));
  CHECK_THAT(error_of({"discretization.artificial_conductivity.alpha=-1"}), Contains("discretization.artificial_conductivity.alpha"));
}

TEST_CASE("discretization.continuity: mass by default, volume for sod.yaml, round trip, errors", "[config]") {
  CHECK(load_config(shock).discretization.continuity == "mass");
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/sod.yaml");
  CHECK(c.discretization.continuity == "volume");
  CHECK(load_config_string(to_yaml(c)).discretization.continuity == "volume");
  CHECK_THAT(error_of({"discretization.continuity=area"}), Contains("discretization.continuity") && Contains("volume"));
  CHECK_THAT(error_of({"discretization.continuity=volume", "discretization.density=summation",
                       "discretization.smoothing_length=constant"}),
             Contains("discretization.continuity") && Contains("discretization.density: continuity"));
}

TEST_CASE("artificial viscosity switch and dynamic wall floor: defaults, round trip, bad values", "[config]") {
  // The shipped tube takes the smooth switch; the defaults with the section given without it.
  const Config c = load_config(shock, {"discretization.artificial_viscosity={alpha: 1.0, beta: 1.0, eta: 0.1}"});
  CHECK(c.discretization.artificial_viscosity.switch_form == "sharp");
  CHECK(c.discretization.artificial_viscosity.switch_width == 1e-4);
  const Config s = load_config(shock, {"discretization.artificial_viscosity.switch=smooth"});
  CHECK(s.discretization.artificial_viscosity.switch_form == "smooth");
  const Config w = load_config(shock, {"discretization.artificial_viscosity.switch=smooth", "discretization.artificial_viscosity.switch_width=0.03"});
  for (const Config* x : {&s, &w}) {
    const Config r = load_config_string(to_yaml(*x));
    CHECK(r.discretization.artificial_viscosity.switch_form == x->discretization.artificial_viscosity.switch_form);
    CHECK(r.discretization.artificial_viscosity.switch_width == x->discretization.artificial_viscosity.switch_width);
  }
  CHECK_THAT(error_of({"discretization.artificial_viscosity.switch=soft"}),
             Contains("artificial_viscosity.switch") && Contains("soft") && Contains("smooth"));
  CHECK_THAT(error_of({"discretization.artificial_viscosity={alpha: 1.0, switch: sharp, switch_width: 0.1}"}),
             Contains("switch_width") && Contains("'smooth' only"));
  for (const char* bad : {"0", "-1e-3", "1.5"})
    CHECK_THAT(error_of({"discretization.artificial_viscosity.switch=smooth", std::string("discretization.artificial_viscosity.switch_width=") + bad}),
               Contains("artificial_viscosity.switch_width") && Contains("(0, 1]"));
  CHECK(c.discretization.artificial_viscosity.switch_offset == 0.0);
  const Config o = load_config(shock, {"discretization.artificial_viscosity.switch=smooth", "discretization.artificial_viscosity.switch_offset=0.25"});
  CHECK(o.discretization.artificial_viscosity.band_offset() == 0.25);
  CHECK(load_config_string(to_yaml(o)).discretization.artificial_viscosity.switch_offset == 0.25);
  CHECK_THAT(error_of({"discretization.artificial_viscosity={alpha: 1.0, switch: sharp, switch_offset: 0.1}"}),
             Contains("switch_offset") && Contains("'smooth' only"));
  for (const char* bad : {"-0.1", "0.6"})
    CHECK_THAT(error_of({"discretization.artificial_viscosity.switch=smooth", std::string("discretization.artificial_viscosity.switch_offset=") + bad}),
               Contains("artificial_viscosity.switch_offset") && Contains("[0, 0.5]"));

  const std::string dam = std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml";
  const Config d = load_config(dam);
  CHECK(d.discretization.wall_density_floor_width == 1e-4);
  const Config d0 = load_config(dam, {"discretization.wall_density_floor_width=0"});
  CHECK(load_config_string(to_yaml(d0)).discretization.wall_density_floor_width == 0.0);
  for (const char* bad : {"-1e-4", "1", "2"}) {
    std::string e = "<no error>";
    try {
      (void)load_config(dam, {std::string("discretization.wall_density_floor_width=") + bad});
    } catch (const ConfigError& x) {
      e = x.what();
    }
    CHECK_THAT(e, Contains("wall_density_floor_width") && Contains("[0, 1)"));
  }
}
