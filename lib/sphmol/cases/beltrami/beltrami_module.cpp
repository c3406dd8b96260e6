// The beltrami case module: its geometry keys, checks and scene size.
#include <cmath>
#include <memory>

#include "sphmol/cases/beltrami/beltrami_case.hpp"
#include "sphmol/cases/beltrami/beltrami_settings.hpp"
#include "sphmol/cases/case_keys.hpp"
#include "sphmol/cases/case_module.hpp"

namespace sphmol {

std::string BeltramiSettings::to_yaml() const {
  return "geometry:\n  box: " + case_keys::yaml_list(box) + "\n  amplitudes: " + case_keys::yaml_list(amplitudes) + "\n";
}

namespace {

CaseRead read_beltrami(CaseReaders& r, const Config& c) {
  auto s = std::make_shared<BeltramiSettings>();
  MapReader geo = r.top.section("geometry", {"box", "amplitudes"});
  s->box = case_keys::read_lengths(geo, "box", 3, "[L, L, L] in m: the periodic cube");
  for (std::size_t i = 1; i < 3; ++i)
    if (std::abs(s->box[i] - s->box[0]) > 1e-12 * s->box[0])
      geo.fail_element("box", i, number_text(s->box[i]) + " differs from box[0] = " + number_text(s->box[0]) +
                                     ": case 'beltrami' needs a cube (the ABC flow has one wavenumber 2 pi / L)");
  if (const auto a = geo.reals("amplitudes")) {
    if (a->size() != 3) geo.fail("amplitudes", "has " + std::to_string(a->size()) + " components, expected 3: [A, B, C] in m/s");
    s->amplitudes = *a;
  }
  const auto& a = s->amplitudes;
  if (a[0] == 0.0 && a[1] == 0.0 && a[2] == 0.0) geo.fail("amplitudes", "are all zero: the fluid would stay at rest");
  case_keys::require_boundary(r, c, {"wall_particles"}, "the cube is periodic and has no walls");
  case_keys::require_viscous(r, c, "is measured by its viscous decay rate nu k^2");
  case_keys::require_no_body_force(r, c, "the ABC flow decays freely");
  if (c.fluid.eos.type == "ideal_gas")
    r.fluid.fail("eos", "case 'beltrami' sets its initial pressure through the densities of a barotropic EOS "
                        "(linear, linear_relative or tait), not ideal_gas");
  const auto& d = c.discretization;
  const double L = s->box[0];
  const double n = d.particles_across > 0 ? d.particles_across
                                          : case_keys::whole_spacings(r.discretization, "spacing", L, d.spacing, "geometry.box[0]");
  CaseRead out{s, {L / n, n * n * n, 0.0}};
  for (int i = 0; i < 3; ++i) out.size.periodic.push_back({geo.where("box"), L});
  return out;
}

}  // namespace

CaseModule beltrami_module() {
  CaseModule m;
  m.name = "beltrami";
  m.description = "decaying Arnold-Beltrami-Childress (Beltrami) flow in a periodic cube against the exact solution";
  m.dimensions = {3};
  m.sections = {"geometry"};
  m.lattice_mass = true;
  m.velocity_scale_from_config = true;  // U = sqrt(A^2 + B^2 + C^2) of geometry.amplitudes
  m.read = read_beltrami;
  m.make3 = [] { return std::make_unique<BeltramiCase>(); };
  return m;
}

}  // namespace sphmol
