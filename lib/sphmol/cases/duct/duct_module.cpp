// The duct case module: its geometry keys, checks and scene size.
#include <cmath>
#include <memory>

#include "sphmol/cases/case_keys.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/cases/duct/duct_case.hpp"
#include "sphmol/cases/duct/duct_settings.hpp"

namespace sphmol {

std::string DuctSettings::to_yaml() const {
  return "geometry:\n  half_widths: " + case_keys::yaml_list({half_width_y, half_width_z}) +
         "\n  length: " + number_text(length) + "\n";
}

namespace {

CaseRead read_duct(CaseReaders& r, const Config& c) {
  auto s = std::make_shared<DuctSettings>();
  MapReader geo = r.top.section("geometry", {"half_widths", "length"});
  const auto hw = case_keys::read_lengths(geo, "half_widths", 2, "[a, b] in m: the walls are at y = +-a and z = +-b");
  s->half_width_y = hw[0];
  s->half_width_z = hw[1];
  s->length = geo.required(geo.real("length"), "length", "periodic length along x in m, > 0");
  geo.check("length", s->length > 0, s->length, "> 0 m");
  const auto& f = c.fluid.body_force;
  if (f[0] == 0.0 || f[1] != 0.0 || f[2] != 0.0) {
    const std::string what = "case 'duct' is driven by a body force along the duct axis only, e.g. body_force: [1e-4, 0, 0]";
    if (r.fluid.has("body_force")) r.fluid.fail("body_force", what);
    r.fluid.fail_missing("body_force", what);
  }
  case_keys::require_boundary(r, c, {"wall_particles"}, "the duct walls are wall-particle layers");
  case_keys::require_viscous(r, c, "is driven by viscosity and measured against the viscous start-up series");

  const auto& d = c.discretization;
  // particles_across counts the fluid particles across the y width 2a.
  const double ny = d.particles_across > 0
                        ? d.particles_across
                        : case_keys::whole_spacings(r.discretization, "spacing", 2.0 * s->half_width_y, d.spacing, "the duct width 2a");
  const double dx = 2.0 * s->half_width_y / ny;
  const double nz = case_keys::whole_spacings(geo, "half_widths", 2.0 * s->half_width_z, dx, "the duct height 2b");
  const double nx = case_keys::whole_spacings(geo, "length", s->length, dx, "geometry.length");
  const double layers = case_keys::wall_layers(c);
  CaseRead out{s, {dx, nx * ny * nz, nx * ((ny + 2 * layers) * (nz + 2 * layers) - ny * nz)}};
  out.size.periodic.push_back({geo.where("length"), s->length});
  return out;
}

}  // namespace

CaseModule duct_module() {
  CaseModule m;
  m.name = "duct";
  m.description = "body-force-driven start-up flow in a rectangular duct against its exact Fourier series";
  m.dimensions = {3};
  m.sections = {"geometry"};
  m.lattice_mass = true;
  m.velocity_scale_from_config = true;  // U = |u_max|, the series' steady centre speed from g, a, b and nu
  m.read = read_duct;
  m.make3 = [] { return std::make_unique<DuctCase>(); };
  return m;
}

}  // namespace sphmol
