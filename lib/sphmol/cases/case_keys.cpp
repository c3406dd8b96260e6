#include "sphmol/cases/case_keys.hpp"

#include <algorithm>
#include <cmath>

#include "sphmol/core/join.hpp"
#include "sphmol/kernels/registry.hpp"

namespace sphmol::case_keys {

double whole_spacings(const MapReader& r, const std::string& key, double length, double dx, const std::string& what) {
  const double n = std::round(length / dx);
  if (!(n >= 1) || std::abs(n * dx - length) > 1e-6 * length)
    r.fail(key, what + " (" + number_text(length) + " m) is not a whole number of the particle spacing " + number_text(dx) +
                    " m (" + number_text(length / dx) + " spacings)");
  return n;
}

std::vector<double> read_lengths(MapReader& r, const std::string& key, int dimension, std::string_view hint) {
  const auto b = r.required(r.reals(key), key, hint);
  if (static_cast<int>(b.size()) != dimension)
    r.fail(key, "has " + std::to_string(b.size()) + " components, expected " + std::to_string(dimension));
  for (std::size_t i = 0; i < b.size(); ++i)
    if (!(b[i] > 0)) r.fail_element(key, i, number_text(b[i]) + " is out of range (allowed: > 0 m)");
  return b;
}

double spacing(const Config& c, double across) {
  return c.discretization.particles_across > 0 ? across / c.discretization.particles_across : c.discretization.spacing;
}

double wall_layers(const Config& c, double extra) {
  const auto& d = c.discretization;
  if (d.wall_layers > 0) return d.wall_layers;
  double support = 0.0;
  switch (c.dimension) {
    case 1: support = kernel_info<1>(d.kernel).support; break;
    case 2: support = kernel_info<2>(d.kernel).support; break;
    default: support = kernel_info<3>(d.kernel).support; break;
  }
  return std::ceil(support * d.smoothing_ratio) + extra;
}

void require_viscous(CaseReaders& r, const Config& c, std::string_view why) {
  if (!(c.fluid.kinematic_viscosity > 0))
    r.fluid.fail("kinematic_viscosity", "case '" + c.case_name + "' " + std::string(why) + "; it needs nu > 0 (got " +
                                            number_text(c.fluid.kinematic_viscosity) + ")");
}

void require_no_body_force(CaseReaders& r, const Config& c, std::string_view why) {
  const auto& f = c.fluid.body_force;
  if (std::any_of(f.begin(), f.end(), [](double g) { return g != 0.0; }))
    r.fluid.fail("body_force", "must be zero for case '" + c.case_name + "' (" + std::string(why) + ")");
}

void require_gravity(CaseReaders& r, const Config& c) {
  const auto& f = c.fluid.body_force;
  bool ok = static_cast<int>(f.size()) == c.dimension && f.back() < 0.0;
  for (std::size_t i = 0; ok && i + 1 < f.size(); ++i) ok = f[i] == 0.0;
  if (ok) return;
  const std::string example = c.dimension == 3 ? "[0, 0, -9.81]" : "[0, -9.81]";
  const std::string what = "case '" + c.case_name + "' needs gravity along the last axis, pointing down, e.g. body_force: " + example;
  if (r.fluid.has("body_force")) r.fluid.fail("body_force", what);
  r.fluid.fail_missing("body_force", what);
}

void require_boundary(CaseReaders& r, const Config& c, const std::vector<std::string>& allowed, std::string_view why) {
  for (const auto& a : allowed)
    if (a == c.discretization.boundary) return;
  r.discretization.fail("boundary", "'" + c.discretization.boundary + "' is not available for case '" + c.case_name + "': " +
                                        std::string(why) + " (allowed: " + join(allowed) + ")");
}

std::string yaml_list(const std::vector<double>& v) { return sphmol::yaml_list(v); }

}  // namespace sphmol::case_keys

namespace sphmol::case_keys {

SceneSize box_scene_size(CaseReaders& r, MapReader& geo, const Config& c, double Lx, double depth, double Ly, bool walls,
                         bool top) {
  const auto& d = c.discretization;
  const double nx = d.particles_across > 0 ? d.particles_across
                                           : whole_spacings(r.discretization, "spacing", Lx, d.spacing, "geometry.box[0]");
  const double dx = Lx / nx;
  const double ny = whole_spacings(geo, "box", depth, dx, "geometry.box[1]");
  const double ny_box = Ly == depth ? ny : whole_spacings(geo, "box", Ly, dx, "the tank height");
  const double layers = wall_layers(c);
  double wall = 0.0;
  if (walls) {
    if (d.boundary == "wall_particles")
      wall = (nx + 2 * layers) * (ny_box + layers + (top ? layers : 0.0)) - nx * ny_box;
    else if (d.boundary == "virtual_repulsive")
      wall = 2.0 * (2.0 * nx + (top ? 2.0 : 1.0) * ny_box);
  }
  SceneSize size{dx, nx * ny, wall};
  if (walls && d.boundary == "ghost") {
    size.mirror_gaps.push_back({geo.where("box"), Lx});
    if (top) size.mirror_gaps.push_back({geo.where("box"), Ly});
  }
  return size;
}

}  // namespace sphmol::case_keys
