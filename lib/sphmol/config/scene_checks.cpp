#include "sphmol/config/scene_checks.hpp"

#include <unistd.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "sphmol/kernels/registry.hpp"

namespace sphmol {

namespace {

std::string shown(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 6);
  return std::string(buf, r.ptr);
}

double kernel_support(int dim, const std::string& name) {
  switch (dim) {
    case 1: return kernel_info<1>(name).support;
    case 2: return kernel_info<2>(name).support;
    default: return kernel_info<3>(name).support;
  }
}

// The key the resolution came from, for messages about it.
const char* resolution_key(const Config& c) { return c.discretization.particles_across > 0 ? "particles_across" : "spacing"; }

// n = round(length / dx) with |n dx - length| within the builders' tolerance, else an error at `key`.
double whole(MapReader& r, const std::string& key, double length, double dx, double tol, const std::string& what) {
  const double n = std::round(length / dx);
  if (!(n >= 1) || std::abs(n * dx - length) > tol)
    r.fail(key, what + " (" + shown(length) + " m) is not a whole number of the particle spacing " + shown(dx) +
                    " m (" + shown(length / dx) + " spacings)");
  return n;
}

}  // namespace

double physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

SceneSize check_scene(const Config& c, SectionReaders& r) {
  const auto& d = c.discretization;
  const auto& g = c.geometry;
  const auto& f = c.fluid;
  const std::string& name = c.case_name;
  const bool shock = name == "shock_tube";
  const double support = kernel_support(c.dimension, d.kernel);  // in units of h
  auto& disc = r.discretization;
  auto& geo = r.geometry;

  // Combinations the case or the assembly cannot build.
  if (d.energy && !shock)
    disc.fail("energy", "case '" + name + "' provides no initial internal energy; the energy equation is for case 'shock_tube'");
  if (name == "dam_break" && d.boundary != "wall_particles")
    disc.fail("boundary", "case 'dam_break' builds its tank from wall particles (got '" + d.boundary + "'; allowed: wall_particles)");
  if (name == "cavity" && d.boundary == "virtual_repulsive")
    disc.fail("boundary", "virtual_repulsive walls exert no shear, so the lid cannot drive the cavity (allowed: wall_particles, ghost)");
  if ((name == "cavity" || name == "taylor_green") && !(f.kinematic_viscosity > 0))
    r.fluid.fail("kinematic_viscosity", "case '" + name + "' needs nu > 0 (its reference is at Re = U L / nu; got " +
                                            shown(f.kinematic_viscosity) + ")");
  if (name == "couette" || name == "poiseuille") {
    // The start-up series (the reference) is a viscous diffusion: nu = 0 leaves nothing to measure.
    if (!(f.kinematic_viscosity > 0))
      r.fluid.fail("kinematic_viscosity", "case '" + name + "' is driven by viscosity and measured against the viscous "
                                              "start-up series; it needs nu > 0 (got " + shown(f.kinematic_viscosity) + ")");
  }
  if ((name == "taylor_green" || name == "cavity") && std::abs(g.box[1] - g.box[0]) > 1e-12 * g.box[0])
    geo.fail_element("box", 1, shown(g.box[1]) + " differs from box[0] = " + shown(g.box[0]) + ": case '" + name +
                                   "' needs a square box (its reference is on the unit square)");
  if (name == "hydrostatic" || name == "dam_break") {
    if (f.body_force.size() != 2 || f.body_force[0] != 0.0 || !(f.body_force[1] < 0.0)) {
      const std::string what = "case '" + name + "' needs gravity [0, -g] with g > 0, e.g. body_force: [0, -9.81]";
      if (r.fluid.has("body_force")) r.fluid.fail("body_force", what);
      r.fluid.fail_missing("body_force", what);
    }
  }
  if (name == "dam_break" && f.eos.type != "tait" && f.eos.type != "linear_relative")
    r.fluid.fail("eos", "case 'dam_break' needs eos.type 'tait' or 'linear_relative' (got '" + f.eos.type +
                            "'): its initial state is the hydrostatic density rho(p) of a gauge-pressure EOS");
  const bool barotropic = f.eos.type != "ideal_gas";
  bool any_force = false;
  for (double x : f.body_force) any_force = any_force || x != 0.0;
  if (d.boundary == "ghost" && any_force && !barotropic)
    r.fluid.fail("body_force", "ghost walls under a body force need a barotropic EOS (the images carry the hydrostatic "
                               "pressure of their position); type 'ideal_gas' has none");
  if (d.wall_pressure == "extrapolated" && !barotropic)
    disc.fail("wall_pressure", "'extrapolated' inverts the EOS for the wall density; type 'ideal_gas' is not barotropic");
  if (d.boundary == "virtual_repulsive" && !(d.repulsive.r0 < support * d.smoothing_ratio))
    disc.fail("repulsive", "r0 = " + shown(d.repulsive.r0) + " spacings must lie inside the kernel support (" +
                               shown(support * d.smoothing_ratio) + " spacings: support " + shown(support) +
                               " h, h = " + shown(d.smoothing_ratio) + " dx)");
  if (d.pair_passes == "fused") {
    std::string stored;
    if (d.boundary == "virtual_repulsive") stored = "boundary: virtual_repulsive";
    else if (d.wall_pressure == "extrapolated") stored = "wall_pressure: extrapolated";
    else if (d.viscosity == "strain_rate") stored = "viscosity: strain_rate";
    else if (d.density == "normalised_summation") stored = "density: normalised_summation";
    if (!stored.empty())
      disc.fail("pair_passes", "'fused' is not available with " + stored + " (it needs the stored pair list; allowed: auto, stored)");
  }
  if (shock) {
    // The exact solution (the reference) exists only without a vacuum: Toro (2009) eq 4.40.
    const auto& L = c.shock_tube.left;
    const auto& R = c.shock_tube.right;
    const double gm = f.eos.gamma, aL = std::sqrt(gm * L.pressure / L.density), aR = std::sqrt(gm * R.pressure / R.density);
    if (2.0 / (gm - 1.0) * (aL + aR) <= R.velocity - L.velocity)
      r.top.fail("shock_tube", "the states separate into a vacuum (right.velocity - left.velocity = " +
                                   shown(R.velocity - L.velocity) + " >= 2 (aL + aR) / (gamma - 1) = " +
                                   shown(2.0 / (gm - 1.0) * (aL + aR)) + " m/s), which the exact Riemann solver does not cover");
  }
  if (shock && c.dimension == 1 && d.particles_across > 0)
    disc.fail("particles_across", "counts particles across the tube width, which the 1D shock tube does not have; give discretization.spacing");

  // Resolution and particle counts, as the builders compute them.
  SceneSize s;
  const char* rk = resolution_key(c);
  const int layers_given = d.wall_layers;
  const auto layers_of = [&](double extra) { return layers_given > 0 ? layers_given : std::ceil(support * d.smoothing_ratio) + extra; };
  std::vector<std::pair<std::string, double>> periodic;  // key path and length
  if (name == "couette" || name == "poiseuille") {
    const double l = g.channel_height, L = g.channel_length;
    const double ny = d.particles_across > 0 ? d.particles_across : whole(disc, "spacing", l, d.spacing, 1e-6 * l, "geometry.channel_height");
    const double dx = l / ny;
    const double nx = whole(geo, "channel_length", L, dx, 1e-6 * L, "geometry.channel_length");
    const double layers = layers_of(0.0);
    s = {dx, nx * ny, 2.0 * layers * nx};
    periodic.emplace_back("channel_length", L);
  } else if (name == "taylor_green" || name == "cavity" || name == "hydrostatic") {
    const double Lx = g.box[0];
    const double nx = d.particles_across > 0 ? d.particles_across : whole(disc, "spacing", Lx, d.spacing, 1e-6 * Lx, "geometry.box[0]");
    const double dx = Lx / nx;
    const double depth = g.box[1];
    const double dx0 = d.particles_across > 0 ? Lx / d.particles_across : d.spacing;
    const double Ly = name == "hydrostatic" ? std::round(1.2 * depth / dx0) * dx0 : depth;
    const double ny = whole(geo, "box", depth, dx, 1e-6 * Ly, "geometry.box[1]");
    const double ny_box = whole(geo, "box", Ly, dx, 1e-6 * Ly, name == "hydrostatic" ? "the tank height 1.2 box[1]" : "geometry.box[1]");
    const double layers = layers_of(0.0);
    double wall = 0.0;
    if (name != "taylor_green") {
      const bool top = name == "cavity";
      if (d.boundary == "wall_particles")
        wall = (nx + 2 * layers) * (ny_box + layers + (top ? layers : 0.0)) - nx * ny_box;
      else if (d.boundary == "virtual_repulsive")
        wall = 2.0 * (2.0 * nx + (top ? 2.0 : 1.0) * ny_box);
    }
    s = {dx, nx * ny, wall};
    if (name == "taylor_green") periodic.emplace_back("box", Lx);
  } else if (name == "dam_break") {
    const double a = g.column[0], H = g.column[1], Lx = g.box[0], Ly = g.box[1];
    const double dx = d.particles_across > 0 ? a / d.particles_across : d.spacing;
    const double nx = whole(geo, "column", a, dx, 1e-6 * a, "geometry.column[0]");
    const double ny = whole(geo, "column", H, dx, 1e-6 * H, "geometry.column[1]");
    const double nxt = whole(geo, "box", Lx, dx, 1e-6 * Lx, "geometry.box[0]");
    const double nyt = whole(geo, "box", Ly, dx, 1e-6 * Ly, "geometry.box[1]");
    const double layers = layers_of(0.0);
    s = {dx, nx * ny, (nxt + 2 * layers) * layers + 2 * layers * nyt};
  } else if (shock) {
    const double L = g.tube_length, W = g.tube_width;
    const double dx = d.particles_across > 0 ? W / d.particles_across : d.spacing;
    const double nx = whole(geo, "tube_length", L, dx, 1e-6 * L, "geometry.tube_length");
    const double ny = c.dimension == 2 ? whole(geo, "tube_width", W, dx, 1e-6 * W, "geometry.tube_width") : 1.0;
    const double layers = layers_of(1.0);
    double wall = 2.0 * layers * ny;
    if (c.dimension == 2 && d.boundary == "virtual_repulsive") wall += 2.0 * 2.0 * nx;
    s = {dx, nx * ny, wall};
    if (c.dimension == 2 && d.boundary == "wall_particles") periodic.emplace_back("tube_width", W);
  }

  // Minimum-image pairs need every periodic length to hold two neighbour radii (core/domain.hpp).
  const double radius = d.smoothing_ratio * (support + d.skin) * s.spacing;
  for (const auto& [key, length] : periodic)
    if (length < 2.0 * radius)
      geo.fail(key, "the periodic length " + shown(length) + " m is shorter than two neighbour radii (2 x " + shown(radius) +
                        " m: (support " + shown(support) + " + skin " + shown(d.skin) + ") h, h = " + shown(d.smoothing_ratio) +
                        " dx); use more particles or a smaller smoothing_ratio or skin");

  // Memory: per particle the state and workspace fields (a few hundred bytes) and, per neighbour
  // within the list radius, the pair list entry and a stored pair's kernel values (32 bytes);
  // the dam break measured 0.6 kB and Taylor-Green (50 neighbours) 2.7 kB per particle.
  const double r_dx = d.smoothing_ratio * (support + d.skin);
  const double neighbours = c.dimension == 1 ? 2.0 * r_dx : c.dimension == 2 ? std::numbers::pi * r_dx * r_dx
                                                                            : 4.0 / 3.0 * std::numbers::pi * r_dx * r_dx * r_dx;
  s.bytes_per_particle = 256.0 + 32.0 * neighbours;
  const double limit = physical_memory_bytes();
  if (limit > 0 && s.bytes() > limit)
    disc.fail(rk, "the run needs about " + shown(s.bytes() / 1e9) + " GB (" + shown(s.fluid) + " fluid + " + shown(s.wall) +
                      " wall particles at about " + shown(s.bytes_per_particle) + " bytes each), more than this machine's " +
                      shown(limit / 1e9) + " GB of memory");

  // Steps: a fixed step, or the CFL bound's smallest possible step (at rest), against max_steps.
  const auto& t = c.time;
  const double max_steps = static_cast<double>(t.max_steps);
  if (t.dt && t.t_end / *t.dt > max_steps)
    r.time.fail("dt", "t_end / dt = " + shown(t.t_end) + " / " + shown(*t.dt) + " = " + shown(t.t_end / *t.dt) +
                          " steps, more than time.max_steps = " + std::to_string(t.max_steps) +
                          " (raise time.max_steps or the step)");
  if (!t.dt) {
    const double h = d.smoothing_ratio * s.spacing;
    double dt_max = std::numeric_limits<double>::infinity();
    if (barotropic && f.eos.sound_speed > 0) dt_max = std::min(dt_max, t.cfl.acoustic * h / f.eos.sound_speed);
    if (f.kinematic_viscosity > 0) dt_max = std::min(dt_max, t.cfl.viscous * h * h / f.kinematic_viscosity);
    if (t.t_end / dt_max > max_steps)
      r.time.fail("max_steps", std::to_string(t.max_steps) + " steps cannot reach time.t_end = " + shown(t.t_end) +
                                   " s: the CFL step is at most " + shown(dt_max) + " s (h = " + shown(h) + " m), so at least " +
                                   shown(t.t_end / dt_max) + " steps are needed");
  }
  if (c.output.checkpoint_every > 0 && t.t_end / c.output.checkpoint_every > max_steps)
    r.output.fail("checkpoint_every", shown(c.output.checkpoint_every) + " s gives " + shown(t.t_end / c.output.checkpoint_every) +
                                          " checkpoints up to time.t_end = " + shown(t.t_end) + " s, more than time.max_steps = " +
                                          std::to_string(t.max_steps) + " steps");
  return s;
}

}  // namespace sphmol
