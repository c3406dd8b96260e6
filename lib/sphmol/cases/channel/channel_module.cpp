// The Couette and Poiseuille case modules: their geometry keys, checks and scene size.
#include <cmath>
#include <memory>

#include "sphmol/cases/case_keys.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/cases/channel/channel_case.hpp"
#include "sphmol/cases/channel/channel_settings.hpp"

namespace sphmol {

std::string ChannelSettings::to_yaml() const {
  return "geometry:\n  channel_height: " + number_text(channel_height) + "\n  channel_length: " + number_text(channel_length) +
         "\n  wall_velocity: " + number_text(wall_velocity) + "\n";
}

namespace {

CaseRead read_channel(CaseReaders& r, const Config& c, bool couette) {
  auto s = std::make_shared<ChannelSettings>();
  s->couette = couette;
  MapReader geo = r.top.section("geometry", {"channel_height", "channel_length", "wall_velocity"});
  s->channel_height = geo.required(geo.real("channel_height"), "channel_height", "distance between the walls in m, > 0");
  geo.check("channel_height", s->channel_height > 0, s->channel_height, "> 0 m");
  s->channel_length = geo.required(geo.real("channel_length"), "channel_length", "periodic length in x in m, > 0");
  geo.check("channel_length", s->channel_length > 0, s->channel_length, "> 0 m");
  if (const auto v = geo.real("wall_velocity")) s->wall_velocity = *v;
  if (!couette) {
    if (s->wall_velocity != 0)
      geo.fail("wall_velocity", "must be 0 for case 'poiseuille' (got " + number_text(s->wall_velocity) +
                                    "; a moving wall is case 'couette')");
    if (c.fluid.body_force[0] == 0) {
      const std::string what = "case 'poiseuille' needs a nonzero x-component (the driving force per "
                               "unit mass, m/s^2), e.g. body_force: [1e-4, 0]";
      if (r.fluid.has("body_force")) r.fluid.fail("body_force", what);
      r.fluid.fail_missing("body_force", what);
    }
  } else if (s->wall_velocity == 0) {
    const std::string what = "case 'couette' needs a nonzero top-plate speed v0 in m/s";
    if (geo.has("wall_velocity")) geo.fail("wall_velocity", what);
    geo.fail_missing("wall_velocity", what);
  }
  case_keys::require_boundary(r, c, {"wall_particles"}, "the channel walls are wall-particle layers");
  // The start-up series (the reference) is a viscous diffusion: nu = 0 leaves nothing to measure.
  case_keys::require_viscous(r, c, "is driven by viscosity and measured against the viscous start-up series");

  const auto& d = c.discretization;
  const double l = s->channel_height, L = s->channel_length;
  const double ny = d.particles_across > 0 ? d.particles_across
                                           : case_keys::whole_spacings(r.discretization, "spacing", l, d.spacing, "geometry.channel_height");
  const double dx = l / ny;
  const double nx = case_keys::whole_spacings(geo, "channel_length", L, dx, "geometry.channel_length");
  CaseRead out{s, {dx, nx * ny, 2.0 * case_keys::wall_layers(c) * nx}};
  out.size.periodic.push_back({geo.where("channel_length"), L});
  return out;
}

CaseModule channel_module(bool couette) {
  CaseModule m;
  m.name = couette ? "couette" : "poiseuille";
  m.description = couette ? "plane Couette start-up flow against its exact series"
                          : "body-force-driven plane Poiseuille start-up flow against its exact series";
  m.dimensions = {2};
  m.sections = {"geometry"};
  m.lattice_mass = true;
  m.read = [couette](CaseReaders& r, const Config& c) { return read_channel(r, c, couette); };
  m.velocity_scale_from_config = true;  // the wall speed (Couette) or the Poiseuille centre speed
  m.make2 = [] { return std::make_unique<ChannelCase>(); };
  return m;
}

}  // namespace

CaseModule couette_module() { return channel_module(true); }
CaseModule poiseuille_module() { return channel_module(false); }

}  // namespace sphmol
