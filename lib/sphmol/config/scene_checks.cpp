#include "sphmol/config/scene_checks.hpp"

#include <unistd.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sphmol/boundary/facing_mirrors.hpp"
#include "sphmol/core/six_digits.hpp"
#include "sphmol/kernels/registry.hpp"

namespace sphmol {

namespace {

double kernel_support(int dim, const std::string& name) {
  switch (dim) {
    case 1: return kernel_info<1>(name).support;
    case 2: return kernel_info<2>(name).support;
    default: return kernel_info<3>(name).support;
  }
}

// The key the resolution came from, for messages about it.
const char* resolution_key(const Config& c) { return c.discretization.particles_across > 0 ? "particles_across" : "spacing"; }

}  // namespace

namespace {
RanksOnMachine g_ranks;  // set_ranks_on_machine()
}  // namespace

void set_ranks_on_machine(RanksOnMachine r) {
  if (r.ranks < 1 || r.here < 1 || r.here > r.ranks)
    throw std::invalid_argument("set_ranks_on_machine: " + std::to_string(r.here) + " of " + std::to_string(r.ranks) + " ranks");
  g_ranks = r;
}

RanksOnMachine ranks_on_machine() { return g_ranks; }

double physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

void check_scene(const Config& c, CaseReaders& r, SceneSize& s) {
  const auto& d = c.discretization;
  const auto& f = c.fluid;
  const double support = kernel_support(c.dimension, d.kernel);  // in units of h
  auto& disc = r.discretization;

  // Term combinations the assembly cannot build.
  const bool barotropic = f.eos.type != "ideal_gas";
  bool any_force = false;
  for (double x : f.body_force) any_force = any_force || x != 0.0;
  if (d.boundary == "ghost" && any_force && !barotropic)
    r.fluid.fail("body_force", "ghost walls under a body force need a barotropic EOS (the images carry the hydrostatic "
                               "pressure of their position); type 'ideal_gas' has none");
  if (d.wall_pressure == "extrapolated" && !barotropic)
    disc.fail("wall_pressure", "'extrapolated' inverts the EOS for the wall density; type 'ideal_gas' is not barotropic");
  if (d.boundary == "virtual_repulsive" && !(d.repulsive.r0 < support * d.smoothing_ratio))
    disc.fail("repulsive", "r0 = " + six_digits(d.repulsive.r0) + " spacings must lie inside the kernel support (" +
                               six_digits(support * d.smoothing_ratio) + " spacings: support " + six_digits(support) +
                               " h, h = " + six_digits(d.smoothing_ratio) + " dx)");
  // The integral approach's gradients have no form for these terms (rhs/assemble.cpp).
  if (d.momentum == "integral_approach" && d.viscosity != "none")
    disc.fail("momentum", "'integral_approach' needs viscosity: none (got '" + d.viscosity + "')");
  if (d.momentum == "integral_approach" && d.density_diffusion > 0.0)
    disc.fail("momentum", "'integral_approach' is not available with density_diffusion (got " + six_digits(d.density_diffusion) + ")");
  if (d.pair_passes == "fused") {
    std::string stored;
    if (d.boundary == "virtual_repulsive") stored = "boundary: virtual_repulsive";
    else if (d.wall_pressure == "extrapolated") stored = "wall_pressure: extrapolated";
    else if (d.viscosity == "strain_rate") stored = "viscosity: strain_rate";
    else if (d.density == "normalised_summation") stored = "density: normalised_summation";
    if (!stored.empty())
      disc.fail("pair_passes", "'fused' is not available with " + stored + " (it needs the stored pair list; allowed: auto, stored)");
  }

  // Minimum-image pairs need every periodic length to hold two neighbour radii (core/domain.hpp).
  const double radius = d.smoothing_ratio * (support + d.skin) * s.spacing;
  for (const auto& [where, length] : s.periodic)
    if (length < 2.0 * radius)
      throw ConfigError(where + ": the periodic length " + six_digits(length) + " m is shorter than two neighbour radii (2 x " + six_digits(radius) +
                        " m: (support " + six_digits(support) + " + skin " + six_digits(d.skin) + ") h, h = " + six_digits(d.smoothing_ratio) +
                        " dx); use more particles or a smaller smoothing_ratio or skin");
  const double support_m = d.smoothing_ratio * support * s.spacing;
  for (const auto& [where, gap] : s.mirror_gaps)
    if (facing_mirrors_too_close(gap, s.spacing, support_m))
      throw ConfigError(where + ": " + facing_mirrors_message(gap, s.spacing, support_m));

  // Memory: per particle the state and workspace fields (a few hundred bytes) and, per neighbour
  // within the list radius, the pair list entry and a stored pair's kernel values (32 bytes);
  // the dam break measured 0.6 kB and Taylor-Green (50 neighbours) 2.7 kB per particle.
  const double r_dx = d.smoothing_ratio * (support + d.skin);
  const double neighbours = c.dimension == 1 ? 2.0 * r_dx : c.dimension == 2 ? std::numbers::pi * r_dx * r_dx
                                                                            : 4.0 / 3.0 * std::numbers::pi * r_dx * r_dx * r_dx;
  s.bytes_per_particle = 256.0 + 32.0 * neighbours;
  // Over MPI ranks this machine holds its ranks' shares of the scene.
  const double limit = physical_memory_bytes();
  const RanksOnMachine rk = ranks_on_machine();
  const double here = s.bytes() * rk.here / rk.ranks;
  if (limit > 0 && here > limit)
    disc.fail(resolution_key(c), "the run needs about " + six_digits(s.bytes() / 1e9) + " GB (" + six_digits(s.fluid) + " fluid + " + six_digits(s.wall) +
                      " wall particles at about " + six_digits(s.bytes_per_particle) + " bytes each)" +
                      (rk.ranks > 1 ? ", " + six_digits(here / 1e9) + " GB of it on this machine (" + std::to_string(rk.here) +
                                          " of the run's " + std::to_string(rk.ranks) + " MPI ranks)"
                                    : std::string()) +
                      ", more than this machine's " + six_digits(limit / 1e9) + " GB of memory");

  // Steps: a fixed step, or the CFL bound's smallest possible step (at rest), against max_steps.
  const auto& t = c.time;
  const double max_steps = static_cast<double>(t.max_steps);
  if (t.dt && t.t_end / *t.dt > max_steps)
    r.time.fail("dt", "t_end / dt = " + six_digits(t.t_end) + " / " + six_digits(*t.dt) + " = " + six_digits(t.t_end / *t.dt) +
                          " steps, more than time.max_steps = " + std::to_string(t.max_steps) +
                          " (raise time.max_steps or the step)");
  if (!t.dt) {
    const double h = d.smoothing_ratio * s.spacing;
    double dt_max = std::numeric_limits<double>::infinity();
    if (barotropic && f.eos.sound_speed > 0) dt_max = std::min(dt_max, t.cfl.acoustic * h / f.eos.sound_speed);
    // The IMEX integrators treat the viscous term implicitly: their CFL step has no viscous limit.
    const bool imex = t.implicit_viscosity();
    const double nu = std::max(f.kinematic_viscosity, s.kinematic_viscosity);
    // The bulk viscosity is explicit with every integrator (rhs/sph_system.hpp, cfl_step).
    const double diffusivity = CflConfig::diffusivity(imex ? 0.0 : nu, d.bulk_zeta(f.eos.sound_speed, h));
    if (diffusivity > 0) dt_max = std::min(dt_max, t.cfl.viscous * h * h / diffusivity);
    if (t.t_end / dt_max > max_steps)
      r.time.fail("max_steps", std::to_string(t.max_steps) + " steps cannot reach time.t_end = " + six_digits(t.t_end) +
                                   " s: the CFL step is at most " + six_digits(dt_max) + " s (h = " + six_digits(h) + " m), so at least " +
                                   six_digits(t.t_end / dt_max) + " steps are needed");
  }
  if (c.output.checkpoint_every > 0 && t.t_end / c.output.checkpoint_every > max_steps)
    r.output.fail("checkpoint_every", six_digits(c.output.checkpoint_every) + " s gives " + six_digits(t.t_end / c.output.checkpoint_every) +
                                          " checkpoints up to time.t_end = " + six_digits(t.t_end) + " s, more than time.max_steps = " +
                                          std::to_string(t.max_steps) + " steps");
}

}  // namespace sphmol
