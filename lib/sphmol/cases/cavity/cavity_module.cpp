// The lid-driven cavity case module: its geometry keys, checks and scene size.
#include <cmath>
#include <memory>
#include <string>

#include "sphmol/cases/case_keys.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/core/six_digits.hpp"
#include "sphmol/cases/cavity/cavity_case.hpp"
#include "sphmol/cases/cavity/cavity_settings.hpp"
#include "sphmol/reference/data_directory.hpp"
#include "sphmol/reference/ghia_table.hpp"

namespace sphmol {

std::string CavitySettings::to_yaml() const {
  return "geometry:\n  box: " + case_keys::yaml_list(box) + "\n  wall_velocity: " + number_text(wall_velocity) + "\n";
}

namespace {

CaseRead read_cavity(CaseReaders& r, const Config& c) {
  auto s = std::make_shared<CavitySettings>();
  MapReader geo = r.top.section("geometry", {"box", "wall_velocity"});
  s->box = case_keys::read_lengths(geo, "box", c.dimension, "[L, L] in m: the square cavity");
  if (const auto v = geo.real("wall_velocity")) s->wall_velocity = *v;
  if (s->wall_velocity == 0) {
    const std::string what = "case 'cavity' needs a nonzero lid speed in m/s";
    if (geo.has("wall_velocity")) geo.fail("wall_velocity", what);
    geo.fail_missing("wall_velocity", what);
  }
  if (std::abs(s->box[1] - s->box[0]) > 1e-12 * s->box[0])
    geo.fail_element("box", 1, number_text(s->box[1]) + " differs from box[0] = " + number_text(s->box[0]) +
                                   ": case 'cavity' needs a square box (its reference is on the unit square)");
  case_keys::require_boundary(r, c, {"wall_particles", "ghost"}, "virtual_repulsive walls exert no shear, so the lid cannot drive the cavity");
  case_keys::require_viscous(r, c, "has its reference at Re = U L / nu");
  CaseRead out{s, case_keys::box_scene_size(r, geo, c, s->box[0], s->box[1], s->box[1], true, true)};
  // Ghia et al. tabulate a few Reynolds numbers: at any other the run has nothing to compare with.
  const double Re = std::abs(s->wall_velocity) * s->box[0] / c.fluid.kinematic_viscosity;
  if (!load_ghia(reference_data_file("ghia1982_u_vertical_centreline.csv"), reference_data_file("ghia1982_v_horizontal_centreline.csv"), Re))
    out.notices.push_back(r.fluid.where("kinematic_viscosity") + ": Re = |U| L / nu = " + six_digits(Re) +
                          " has no centre-line table of Ghia, Ghia & Shin (1982) in verification/ghia1982_*.csv: "
                          "the centre lines are not compared (u_max, v_max, u_rms, v_rms are null); the steadiness "
                          "measures are kept");
  return out;
}

}  // namespace

CaseModule cavity_module() {
  CaseModule m;
  m.name = "cavity";
  m.description = "lid-driven square cavity against the Ghia, Ghia & Shin (1982) centre-line tables";
  m.dimensions = {2};
  m.sections = {"geometry"};
  m.position_noise = true;
  m.lattice_mass = true;
  m.velocity_scale_from_config = true;  // U = |geometry.wall_velocity|, the lid speed
  m.read = read_cavity;
  m.make2 = [] { return std::make_unique<CavityCase>(); };
  return m;
}

}  // namespace sphmol
