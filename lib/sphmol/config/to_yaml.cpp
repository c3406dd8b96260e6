// to_yaml: the resolved config, every default filled in, in the layout of config/defaults.yaml.
// Numbers use the shortest text that parses back to the same double, so load(to_yaml(c)) == c.
#include <yaml-cpp/yaml.h>

#include <charconv>
#include <utility>
#include <sstream>

#include "sphmol/config/yaml_reader.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/probes/probe_config.hpp"

namespace sphmol {

namespace {

std::string num(double v) { return number_text(v); }
std::string list(const std::vector<double>& v) { return yaml_list(v); }
// Free text (paths) double-quoted with YAML escapes; names from fixed lists go out plain.
std::string quoted(const std::string& s) { return yaml_quoted(s); }

}  // namespace

std::string to_yaml(const Config& c) {
  std::ostringstream y;
  const auto& f = c.fluid;
  const auto& d = c.discretization;
  const auto& t = c.time;
  const auto& o = c.output;
  // The path escaped: a newline in it would end the comment and break the file.
  y << "# Resolved sph-mol configuration" << (c.source.empty() ? "" : " (from " + yaml_comment_text(c.source) + ")")
    << "; all defaults filled in.\n";
  y << "case: " << c.case_name << "\n";
  y << "dimension: " << c.dimension << "\n";
  y << "fluid:\n";
  // 0: the case's own initial states give the densities (and the key is not allowed).
  if (c.fluid.density > 0) y << "  density: " << num(f.density) << "\n";
  y << "  kinematic_viscosity: " << num(f.kinematic_viscosity) << "\n"
    << "  eos:\n"
    << "    type: " << f.eos.type << "\n";
  if (f.eos.type == "ideal_gas")
    y << "    gamma: " << num(f.eos.gamma) << "\n";
  else
    y << "    sound_speed: " << num(f.eos.sound_speed) << "\n";
  if (f.eos.type == "tait")
    y << "    gamma: " << num(f.eos.gamma) << "\n"
      << "    clamp_negative: " << (f.eos.clamp_negative ? "true" : "false") << "\n";
  y << "    background_pressure: " << num(f.eos.background_pressure) << "\n";
  y << "  body_force: " << list(f.body_force) << "\n"
    << "  body_force_ramp: " << num(f.body_force_ramp) << "\n";
  if (c.case_settings) y << c.case_settings->to_yaml();
  y << "discretization:\n";
  // Exactly one of the two is set; the other stays at its 0 "not given" value.
  if (d.particles_across > 0)
    y << "  particles_across: " << d.particles_across << "\n";
  else
    y << "  spacing: " << num(d.spacing) << "\n";
  y << "  kernel: " << d.kernel << "\n"
    << "  smoothing_ratio: " << num(d.smoothing_ratio) << "\n"
    << "  density: " << d.density << "\n"
    << "  momentum: " << d.momentum << "\n"
    << "  viscosity: " << d.viscosity << "\n"
    << "  laplacian_correction: " << d.laplacian_correction << "\n"
    << "  xsph: " << num(d.xsph) << "\n"
    << "  boundary: " << d.boundary << "\n"
    << "  wall_pressure: " << d.wall_pressure << "\n";
  if (d.wall_pressure == "dynamic" || d.wall_density_floor_width_given) y << "  wall_density_floor_width: " << num(d.wall_density_floor_width) << "\n";
  if (d.boundary == "ghost") y << "  wall_slip: " << d.wall_slip << "\n";
  if (d.boundary == "virtual_repulsive")
    y << "  repulsive:\n"
      << "    strength: " << num(d.repulsive.strength) << "\n"
      << "    p1: " << num(d.repulsive.p1) << "\n"
      << "    p2: " << num(d.repulsive.p2) << "\n"
      << "    r0: " << num(d.repulsive.r0) << "\n";
  y << "  wall_model: " << d.wall_model << "\n";
  // Written only where it is read (the loader says it has no effect elsewhere).
  if (d.wall_model == "morris") y << "  wall_beta_max: " << num(d.wall_beta_max) << "\n";
  y
    << "  wall_layers: " << d.wall_layers << "\n"
    << "  neighbor_search: " << d.neighbor_search << "\n"
    << "  skin: " << num(d.skin) << "\n"
    << "  reorder: " << (d.reorder ? "true" : "false") << "\n"
    << "  pair_passes: " << d.pair_passes << "\n"
    << "  combine_terms: " << (d.combine_terms ? "true" : "false") << "\n";
  if (d.artificial_viscosity.enabled)
    y << "  artificial_viscosity: {form: " << d.artificial_viscosity.form << ", alpha: " << num(d.artificial_viscosity.alpha)
      << ", beta: " << num(d.artificial_viscosity.beta)
      << (d.artificial_viscosity.form == "monaghan_1992" ? ", eta: " + num(d.artificial_viscosity.eta) : std::string())
      << ", switch: " << d.artificial_viscosity.switch_form
      << (d.artificial_viscosity.switch_form == "smooth" ? ", switch_width: " + num(d.artificial_viscosity.switch_width) +
                                                               ", switch_offset: " + num(d.artificial_viscosity.switch_offset)
                                                         : std::string())
      << "}\n";
  if (d.artificial_conductivity.enabled)
    y << "  artificial_conductivity: {alpha: " << num(d.artificial_conductivity.alpha) << "}\n";
  if (d.position_noise > 0) y << "  position_noise: " << num(d.position_noise) << "\n";
  // The choice written out, not `auto`: the run's config.yaml (and a restart from it) keeps the
  // correction the run took whatever the rule says later.
  if (d.position_correction.setting == "auto" && d.position_correction.cell_reynolds >= 0.0)  // by the rule
    y << "  # position_correction: auto chose " << d.position_correction.chosen << ": " << d.position_correction.reason << "\n";
  if (!d.position_correction.setting.empty()) y << "  position_correction: " << d.position_correction.chosen << "\n";
  if (d.particle_shifting.enabled)
    y << "  particle_shifting: {coefficient: " << num(d.particle_shifting.coefficient)
      << ", velocity: " << num(d.particle_shifting.velocity)
      << ", correction: " << (d.particle_shifting.correction ? "true" : "false") << "}\n";
  if (d.transport_velocity.enabled)
    y << "  transport_velocity: {background_pressure: " << num(d.transport_velocity.background_pressure)
      << ", step_factor: " << num(d.transport_velocity.step_factor)
      << ", extra_stress: " << (d.transport_velocity.extra_stress ? "true" : "false") << "}\n";
  y << "  energy: " << (d.energy ? "true" : "false") << "\n"
    << "  smoothing_length: " << d.smoothing_length << "\n";
  if (d.density_diffusion > 0) y << "  density_diffusion: " << num(d.density_diffusion) << "\n";
  if (d.density_diffusion_form != "molteni_colagrossi") y << "  density_diffusion_form: " << d.density_diffusion_form << "\n";
  if (d.bulk_viscosity > 0) y << "  bulk_viscosity: " << num(d.bulk_viscosity) << "\n";
  if (d.continuity != "mass") y << "  continuity: " << d.continuity << "\n";
  if (d.particle_mass != "summation") y << "  particle_mass: " << d.particle_mass << "\n";
  y << "time:\n"
    << "  t_end: " << num(t.t_end) << "\n"
    << "  integrator: " << t.integrator << "\n";
  // Only what the integrator reads: the file loads back without notices of unused settings.
  if (t.takes_table()) y << "  table: " << t.table << "\n";
  if (t.takes_tolerances()) y << "  rtol: " << num(t.rtol) << "\n" << "  atol: " << num(t.atol) << "\n";
  if (t.takes_cfl())
    y << "  cfl:\n"
      << "    acoustic: " << num(t.cfl.acoustic) << "\n"
      << "    force: " << num(t.cfl.force) << "\n"
      << "    viscous: " << num(t.cfl.viscous) << "\n";
  if (t.dt)
    y << "  dt: " << num(*t.dt) << "\n";
  if (t.implicit_viscosity()) {
    y << "  krylov:\n    solver: " << t.krylov.solver << "\n";
    if (t.integrator == "leapfrog_imex") y << "    tolerance: " << num(t.krylov.tolerance) << "\n";
    y << "    max_iterations: " << t.krylov.max_iterations << "\n";
  }
  else
    y << "  # dt: not set (adaptive step)\n";
  y << "  max_steps: " << t.max_steps << "\n";
  y << "output:\n"
    << "  directory: " << quoted(o.directory) << "\n"
    ;
  if (o.every) y << "  every: " << num(*o.every) << "\n";  // output.every
  else y << "  times: " << list(o.times) << "\n";
  y
    << "  profiles: " << (o.profiles ? "true" : "false") << "\n"
    << "  vtk: " << (o.vtk ? "true" : "false") << "\n";
  if (o.vtk) y << "  vtk_walls: " << (o.vtk_walls ? "true" : "false") << "\n";
  y
    << "  vtk_ghosts: " << (o.vtk_ghosts ? "true" : "false") << "\n"
    << "  plots: " << (o.plots ? "true" : "false") << "\n"
    << "  checkpoint_every: " << num(o.checkpoint_every) << "\n";
  y << "health:\n"
    << "  max_outflow_fraction: " << num(c.health.max_outflow_fraction) << "\n";
  y << probes_to_yaml(c.probes);  // probes/probe_config.hpp
  return y.str();
}

}  // namespace sphmol
