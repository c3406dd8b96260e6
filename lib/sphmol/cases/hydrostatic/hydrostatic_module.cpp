// The hydrostatic tank case module: its geometry keys, checks and scene size.
#include <cmath>
#include <memory>

#include "sphmol/cases/case_keys.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/cases/hydrostatic/hydrostatic_case.hpp"
#include "sphmol/cases/hydrostatic/hydrostatic_settings.hpp"

namespace sphmol {

std::string HydrostaticSettings::to_yaml() const { return "geometry:\n  box: " + case_keys::yaml_list(box) + "\n"; }

namespace {

CaseRead read_hydrostatic(CaseReaders& r, const Config& c) {
  auto s = std::make_shared<HydrostaticSettings>();
  MapReader geo = r.top.section("geometry", {"box"});
  s->box = case_keys::read_lengths(geo, "box", c.dimension, "[width, depth] of the water column in m");
  case_keys::require_gravity(r, c);
  const double width = s->box[0], depth = s->box[1];
  // The side walls reach 1.2 x depth, a whole number of spacings (HydrostaticCase::build).
  const double dx0 = case_keys::spacing(c, width);
  const double tank = std::round(1.2 * depth / dx0) * dx0;
  return {s, case_keys::box_scene_size(r, geo, c, width, depth, tank, true, false)};
}

}  // namespace

CaseModule hydrostatic_module() {
  CaseModule m;
  m.name = "hydrostatic";
  m.description = "water column at rest in a tank against p = rho0 g (depth - y)";
  m.dimensions = {2};
  m.sections = {"geometry"};
  m.position_noise = true;
  m.free_surface = true;
  m.read = read_hydrostatic;
  m.make2 = [] { return std::make_unique<HydrostaticCase>(); };
  return m;
}

}  // namespace sphmol
