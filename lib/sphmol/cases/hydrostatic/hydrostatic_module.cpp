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

// The 3D tank as HydrostaticCase<3> builds it (scenes/box_scene.hpp): fluid [0, W] x [0, B] x [0, H]
// in a tank of height T, wall particles on the four sides and the floor (the open top has none).
SceneSize tank_3d_size(CaseReaders& r, MapReader& geo, const Config& c, const std::vector<double>& box, double T) {
  case_keys::require_boundary(r, c, {"wall_particles", "ghost"}, "the 3D tank has no virtual_repulsive walls");
  const auto& d = c.discretization;
  const double nx = d.particles_across > 0 ? d.particles_across
                                           : case_keys::whole_spacings(r.discretization, "spacing", box[0], d.spacing,
                                                                       "geometry.box[0]");
  const double dx = box[0] / nx;
  const double ny = case_keys::whole_spacings(geo, "box", box[1], dx, "geometry.box[1]");
  const double nz = case_keys::whole_spacings(geo, "box", box[2], dx, "geometry.box[2]");
  const double nz_tank = case_keys::whole_spacings(geo, "box", T, dx, "the tank height");
  const double layers = case_keys::wall_layers(c);
  SceneSize size;
  size.spacing = dx;
  size.fluid = nx * ny * nz;
  if (d.boundary == "wall_particles") size.wall = (nx + 2 * layers) * (ny + 2 * layers) * (nz_tank + layers) - nx * ny * nz_tank;
  return size;
}

CaseRead read_hydrostatic(CaseReaders& r, const Config& c) {
  auto s = std::make_shared<HydrostaticSettings>();
  MapReader geo = r.top.section("geometry", {"box"});
  s->box = case_keys::read_lengths(geo, "box", c.dimension,
                                   c.dimension == 3 ? "[width, breadth, depth] of the water column in m"
                                                    : "[width, depth] of the water column in m");
  case_keys::require_gravity(r, c);
  const double width = s->box[0], depth = s->box.back();
  // The side walls reach 1.2 x depth, a whole number of spacings (HydrostaticCase::build).
  const double dx0 = case_keys::spacing(c, width);
  const double tank = std::round(1.2 * depth / dx0) * dx0;
  if (c.dimension == 3) return {s, tank_3d_size(r, geo, c, s->box, tank)};
  return {s, case_keys::box_scene_size(r, geo, c, width, depth, tank, true, false)};
}

}  // namespace

CaseModule hydrostatic_module() {
  CaseModule m;
  m.name = "hydrostatic";
  m.description = "water column at rest in a tank against p = rho0 g (depth - z), z the last coordinate";
  m.dimensions = {2, 3};
  m.sections = {"geometry"};
  m.position_noise = true;
  m.lattice_mass = true;
  m.free_surface = true;
  m.read = read_hydrostatic;
  m.make2 = [] { return std::make_unique<HydrostaticCase<2>>(); };
  m.make3 = [] { return std::make_unique<HydrostaticCase<3>>(); };
  return m;
}

}  // namespace sphmol
