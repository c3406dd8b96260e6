// The hydrostatic tank case module: its geometry keys, checks and scene size.
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

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
  if (d.boundary == "ghost")
    for (int k = 0; k < 2; ++k) size.mirror_gaps.push_back({geo.where("box"), box[k]});
  return size;
}

// The resolution when neither particles_across nor spacing is given: the column's error sits in its
// top row (half a kernel), whose share of the fitted gradient is about -2.5 / N^2 for N rows in the
// depth; at N = 36 (-0.19 %) the column's compression at the default c0 (+0.125 %, below) leaves the
// gradient within 0.1 % of rho0 g and p_rms about 0.002 of rho0 g H, in any tank shape
// (docs/verification.md). N is the smallest count from 36 on (up to 72) for which the width (and
// breadth) are whole numbers of H / N; 0 if there is none.
constexpr int kDefaultRows = 36;

// The distance from the tank's virtual repulsive particles to the nearest fluid particles at the
// start, in spacings: the default and the largest repulsive.r0.
constexpr double kVirtualWallGap = 0.5;

int default_rows(const std::vector<double>& box) {
  const double depth = box.back();
  for (int n = kDefaultRows; n <= 2 * kDefaultRows; ++n) {
    const double dx = depth / n;
    bool whole = true;
    for (std::size_t k = 0; k + 1 < box.size(); ++k) {
      const double m = std::round(box[k] / dx);
      // Tighter than the scene's own check (1e-6), which recomputes the spacing from the width.
      whole = whole && m >= 1 && std::abs(m * dx - box[k]) <= 1e-9 * box[k];
    }
    if (whole) return n;
  }
  return 0;
}

// The sound speed when it is not given: c0 = 20 sqrt(g H). The weakly compressible column is denser
// than rho0 by g H / (2 c0^2) on average and its pressure gradient steeper than rho0 g by that much:
// 0.125 % at 20 sqrt(g H), 0.5 % at the usual 10 sqrt(g H) (Monaghan 1994's Mach-0.1 rule with the
// long-wave speed); a gradient within 0.2 % needs c0 >= 16 sqrt(g H).
std::pair<double, std::string> tank_sound_speed(const Config& c) {
  const double g = -c.fluid.body_force.back();
  const double depth = c.settings<HydrostaticSettings>().box.back();
  return {20.0 * std::sqrt(g * depth),
          "20 sqrt(g H) with g = " + number_text(g) + " m/s^2 and the depth H = " + number_text(depth) + " m"};
}

CaseRead read_hydrostatic(CaseReaders& r, const Config& c) {
  auto s = std::make_shared<HydrostaticSettings>();
  MapReader geo = r.top.section("geometry", {"box"});
  s->box = case_keys::read_lengths(geo, "box", c.dimension,
                                   c.dimension == 3 ? "[width, breadth, depth] of the water column in m"
                                                    : "[width, depth] of the water column in m");
  case_keys::require_gravity(r, c);
  // The tank's virtual particles lie on the wall lines, half a spacing from the outermost fluid rows
  // (scenes/box_scene.hpp); a cut-off beyond that pushes the start lattice off the walls at 2^p1 D / r
  // and the run blows up in its first steps (Niedoba 2012, §2.2.5: r0 must not reach the particles'
  // initial positions).
  if (c.discretization.boundary == "virtual_repulsive" && c.discretization.repulsive.r0 > kVirtualWallGap)
    r.discretization.fail("repulsive", "r0 = " + number_text(c.discretization.repulsive.r0) +
                                           " spacings reaches the fluid's outermost rows, " + number_text(kVirtualWallGap) +
                                           " spacings from the tank's virtual particles: the start lattice would be pushed "
                                           "off the walls; give r0 <= " + number_text(kVirtualWallGap) + " (the default)");
  const double width = s->box[0], depth = s->box.back();
  // Without a resolution key: N rows in the depth (default_rows); the size checks below then read it.
  std::optional<Config> derived;
  std::string rule;
  if (c.discretization.particles_across == 0 && !(c.discretization.spacing > 0.0)) {
    const int rows = default_rows(s->box);
    if (rows == 0)
      r.discretization.fail_missing(
          "particles_across", "or discretization.spacing: no number of rows in the depth " + number_text(depth) + " m from " +
                                  std::to_string(kDefaultRows) + " to " + std::to_string(2 * kDefaultRows) +
                                  " makes the other sides of geometry.box whole numbers of the spacing");
    derived = c;
    derived->discretization.spacing = depth / rows;
    rule = std::to_string(rows) + " rows in the depth of the column, the tank's default resolution";
  }
  const Config& cs = derived ? *derived : c;
  // The side walls reach 1.2 x depth, a whole number of spacings (HydrostaticCase::build).
  const double dx0 = case_keys::spacing(cs, width);
  const double tank = std::round(1.2 * depth / dx0) * dx0;
  CaseRead out{s,
               c.dimension == 3 ? tank_3d_size(r, geo, cs, s->box, tank)
                                : case_keys::box_scene_size(r, geo, cs, width, depth, tank, true, false),
               rule};
  out.open_to_outflow = true;  // the tank's open top
  return out;
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
  m.spacing_from_scene = true;
  m.default_sound_speed = tank_sound_speed;
  m.read = read_hydrostatic;
  m.defaults = [](Config& c) { c.discretization.repulsive.r0 = kVirtualWallGap; };
  m.make2 = [] { return std::make_unique<HydrostaticCase<2>>(); };
  m.make3 = [] { return std::make_unique<HydrostaticCase<3>>(); };
  return m;
}

}  // namespace sphmol
