// The Taylor-Green case module: its geometry keys, checks and scene size.
#include <cmath>
#include <memory>

#include "sphmol/cases/case_keys.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/cases/taylor_green/taylor_green_case.hpp"
#include "sphmol/cases/taylor_green/taylor_green_settings.hpp"

namespace sphmol {

std::string TaylorGreenSettings::to_yaml() const {
  return "geometry:\n  box: " + case_keys::yaml_list(box) + "\n  velocity_amplitude: " + number_text(velocity_amplitude) + "\n";
}

namespace {

CaseRead read_taylor_green(CaseReaders& r, const Config& c) {
  auto s = std::make_shared<TaylorGreenSettings>();
  MapReader geo = r.top.section("geometry", {"box", "velocity_amplitude"});
  s->box = case_keys::read_lengths(geo, "box", c.dimension, "[L, L] in m: the periodic square");
  if (const auto v = geo.real("velocity_amplitude")) s->velocity_amplitude = *v;
  geo.check("velocity_amplitude", s->velocity_amplitude > 0, s->velocity_amplitude, "> 0 m/s");
  if (std::abs(s->box[1] - s->box[0]) > 1e-12 * s->box[0])
    geo.fail_element("box", 1, number_text(s->box[1]) + " differs from box[0] = " + number_text(s->box[0]) +
                                   ": case 'taylor_green' needs a square box (its reference is on the unit square)");
  case_keys::require_boundary(r, c, {"wall_particles"}, "the box is periodic and has no walls");
  case_keys::require_viscous(r, c, "has its reference at Re = U L / nu");
  // A uniform force in the periodic box accelerates the whole flow; the exact vortex decays freely.
  case_keys::require_no_body_force(r, c, "the Taylor-Green vortex decays freely");
  CaseRead out{s, case_keys::box_scene_size(r, geo, c, s->box[0], s->box[1], s->box[1], false, false)};
  out.size.periodic.push_back({geo.where("box"), s->box[0]});
  return out;
}

}  // namespace

CaseModule taylor_green_module() {
  CaseModule m;
  m.name = "taylor_green";
  m.description = "decaying Taylor-Green vortex in a periodic square against the exact solution";
  m.dimensions = {2};
  m.sections = {"geometry"};
  m.position_noise = true;
  m.lattice_mass = true;
  m.velocity_scale_from_config = true;  // U = geometry.velocity_amplitude
  m.read = read_taylor_green;
  m.make2 = [] { return std::make_unique<TaylorGreenCase>(); };
  return m;
}

}  // namespace sphmol
