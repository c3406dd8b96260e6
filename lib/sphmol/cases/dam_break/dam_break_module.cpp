// The dam-break case module: its geometry keys, checks and scene size.
#include <memory>

#include "sphmol/cases/case_keys.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/cases/dam_break/dam_break_case.hpp"
#include "sphmol/cases/dam_break/dam_break_settings.hpp"
#include "sphmol/reference/dam_break_front.hpp"

namespace sphmol {

std::string DamBreakSettings::to_yaml() const {
  return "geometry:\n  box: " + case_keys::yaml_list(box) + "\n  column: " + case_keys::yaml_list(column) + "\n";
}

namespace {

CaseRead read_dam_break(CaseReaders& r, const Config& c) {
  auto s = std::make_shared<DamBreakSettings>();
  MapReader geo = r.top.section("geometry", {"box", "column"});
  s->box = case_keys::read_lengths(geo, "box", c.dimension, "[Lx, Ly] of the tank in m");
  const auto col = geo.required(geo.reals("column"), "column", "[width, height] of the water column in m");
  if (col.size() != 2) geo.fail("column", "has " + std::to_string(col.size()) + " components, expected 2");
  for (std::size_t i = 0; i < 2; ++i)
    if (col[i] <= 0 || col[i] > s->box[i])
      geo.fail_element("column", i, number_text(col[i]) + " is out of range (allowed: > 0 m and <= geometry.box[" +
                                        std::to_string(i) + "] = " + number_text(s->box[i]) + ")");
  s->column = col;
  case_keys::require_gravity(r, c);
  // The experiments and Ritter's solution release the column under full gravity at t = 0.
  if (c.fluid.body_force_ramp > 0.0)
    r.fluid.fail("body_force_ramp", "must be 0 for case 'dam_break': the column is released under full gravity at t = 0, as "
                                    "in the experiments and Ritter's solution it is measured against (got " +
                                        number_text(c.fluid.body_force_ramp) + " s)");
  case_keys::require_boundary(r, c, {"wall_particles"}, "the tank is built from wall particles");
  if (c.fluid.eos.type != "tait" && c.fluid.eos.type != "linear_relative")
    r.fluid.fail("eos", "case 'dam_break' needs eos.type 'tait' or 'linear_relative' (got '" + c.fluid.eos.type +
                            "'): its initial state is the hydrostatic density rho(p) of a gauge-pressure EOS");
  const double a = col[0], H = col[1], Lx = s->box[0], Ly = s->box[1];
  const double dx = case_keys::spacing(c, a);
  const double nx = case_keys::whole_spacings(geo, "column", a, dx, "geometry.column[0]");
  const double ny = case_keys::whole_spacings(geo, "column", H, dx, "geometry.column[1]");
  const double nxt = case_keys::whole_spacings(geo, "box", Lx, dx, "geometry.box[0]");
  const double nyt = case_keys::whole_spacings(geo, "box", Ly, dx, "geometry.box[1]");
  const double layers = case_keys::wall_layers(c);
  CaseRead out{s, {dx, nx * ny, (nxt + 2 * layers) * layers + 2 * layers * nyt}};
  out.open_to_outflow = true;  // the tank's open top
  if (!experiments_apply(a, H))
    out.notices.push_back(geo.where("column") + ": H/a = " + number_text(H / a) +
                          ": the experiments of Martin & Moyce (1952, n^2 = 2) and Koshizuka & Oka (1996) have H = 2a "
                          "and are not compared (null in final_errors, empty cells in front.csv); the Ritter front is");
  return out;
}

}  // namespace

CaseModule dam_break_module() {
  CaseModule m;
  m.name = "dam_break";
  m.description = "collapse of a water column in a tank against the Martin & Moyce (1952) front positions";
  m.dimensions = {2};
  m.sections = {"geometry"};
  m.free_surface = true;
  m.read = read_dam_break;
  m.make2 = [] { return std::make_unique<DamBreakCase>(); };
  return m;
}

}  // namespace sphmol
