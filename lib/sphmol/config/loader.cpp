// load_config: YAML text -> overrides applied to the tree -> validated Config. The schema lives
// here, read section by section with MapReader (yaml_reader.hpp), so each key's type, default,
// range and message are in one place; config/README.md documents the same rules.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <charconv>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>

#include "sphmol/config/config.hpp"
#include "sphmol/io/input_file.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/ark_pairs.hpp"
#include "sphmol/config/erk_tables.hpp"
#include "sphmol/config/position_correction.hpp"
#include "sphmol/config/scene_checks.hpp"
#include "sphmol/config/yaml_reader.hpp"
#include "sphmol/core/join.hpp"
#include "sphmol/kernels/registry.hpp"
#include "sphmol/run/timed_output_files.hpp"
#include "sphmol/probes/probe_config.hpp"

namespace sphmol {

namespace {

std::string trim(std::string s) {
  const auto b = s.find_first_not_of(" \t");
  const auto e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string{} : s.substr(b, e - b + 1);
}

// Applies "a.b.c=value" to the tree, creating missing sections; records the origin so that
// errors about the value name the override. Unknown paths are caught by validation, which
// then points at this override.
void apply_override(YAML::Node& root, const std::string& text, YamlOrigin& origin) {
  const std::string where = "--set " + text;
  const auto eq = text.find('=');
  if (eq == std::string::npos)
    throw ConfigError(where + ": malformed override: expected key.path=value (e.g. time.rtol=1e-8)");
  const std::string path = trim(text.substr(0, eq));
  std::vector<std::string> segments;
  for (std::size_t start = 0;;) {
    const auto dot = path.find('.', start);
    segments.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  for (const auto& s : segments)
    if (s.empty())
      throw ConfigError(where + ": malformed override: empty key in '" + path +
                        "' (expected key.path=value, e.g. time.rtol=1e-8)");
  YAML::Node value;
  try {
    value = YAML::Load(text.substr(eq + 1));
  } catch (const YAML::ParserException& e) {
    throw ConfigError(where + ": " + path + ": YAML syntax error in the value: " + e.msg);
  }
  if (!root.IsDefined() || root.IsNull()) root.reset(YAML::Node(YAML::NodeType::Map));
  if (!root.IsMap()) return;  // validation reports the malformed document itself
  // key=null (or ~) takes the key out, so the default or another key applies: time.dt=null for CFL
  // steps, particles_across=null beside a spacing. A key that is not there leaves nothing to do.
  const std::string raw = trim(text.substr(eq + 1));
  if (raw == "null" || raw == "~" || raw == "Null" || raw == "NULL") {
    origin.add_override(path, text);  // messages about the absent key name the removal
    YAML::Node cur;
    cur.reset(root);
    for (std::size_t i = 0; i + 1 < segments.size(); ++i) {
      if (!cur.IsMap() || !cur[segments[i]].IsDefined()) return;
      YAML::Node child = cur[segments[i]];
      cur.reset(child);
    }
    if (cur.IsMap()) cur.remove(segments.back());
    return;
  }
  YAML::Node cur;
  cur.reset(root);
  std::string sofar;
  for (std::size_t i = 0; i + 1 < segments.size(); ++i) {
    sofar += (sofar.empty() ? "" : ".") + segments[i];
    if (!cur.IsMap())
      throw ConfigError(where + ": " + path + ": '" + sofar + "' is not a section, cannot set keys inside it");
    YAML::Node next = cur[segments[i]];
    if (!next.IsDefined() || next.IsNull()) cur[segments[i]] = YAML::Node(YAML::NodeType::Map);
    YAML::Node child = cur[segments[i]];
    cur.reset(child);
  }
  if (!cur.IsMap())
    throw ConfigError(where + ": " + path + ": '" + sofar + "' is not a section, cannot set keys inside it");
  cur[segments.back()] = value;
  origin.add_override(path, text);
}

// The kernel's support radius in units of h.
template <int D>
double check_kernel(const MapReader& r, const std::string& name) {
  std::vector<std::string> names;
  for (auto n : kernel_names<D>()) names.emplace_back(n);
  r.choice("kernel", name, names);
  try {
    return kernel_info<D>(name).support;  // rejects kernels their source does not define in D
  } catch (const std::invalid_argument& e) {
    r.fail("kernel", e.what());
  }
}

// The scene's velocity scale U from the config alone (Case::velocity_scale), or 0 when the case gives none.
double config_velocity_scale(const Config& c, const CaseModule& module) {
  if (!module.velocity_scale_from_config) return 0.0;
  const double U = c.dimension == 1 ? make_case<1>(c)->velocity_scale(c)
                   : c.dimension == 2 ? make_case<2>(c)->velocity_scale(c) : make_case<3>(c)->velocity_scale(c);
  return std::isfinite(U) && U > 0.0 ? U : 0.0;
}

// Defaults derived from the scene's velocity scale U (Case::velocity_scale), for the cases that know
// it from the config alone: the artificial sound speed c = 10 U (Mach 0.1, density variations ~ Ma^2
// = 1 %; Monaghan 1994) and the particle-shifting velocity. Without U, both must be given. A case
// with its own sound-speed rule (CaseModule::default_sound_speed, e.g. the tank's depth) uses that.
void resolve_velocity_defaults(Config& c, const CaseModule& module, MapReader& fluid, MapReader& disc) {
  const bool need_c = c.fluid.eos.type != "ideal_gas" && !(c.fluid.eos.sound_speed > 0.0);
  auto& ps = c.discretization.particle_shifting;
  const bool need_u = ps.enabled && !(ps.velocity > 0.0);
  if (!need_c && !need_u) return;
  const double U = config_velocity_scale(c, module);
  const bool known = U > 0.0;
  if (need_c && module.default_sound_speed) {
    MapReader eos = fluid.section("eos", {"type", "sound_speed", "gamma", "background_pressure", "clamp_negative"});
    const auto [cs, rule] = module.default_sound_speed(c);
    if (!(std::isfinite(cs) && cs > 0.0))
      eos.fail_missing("sound_speed", "artificial speed of sound c in m/s, > 0 (" + rule + " gives " + number_text(cs) + ")");
    c.fluid.eos.sound_speed = cs;
    c.notices.push_back(eos.where("sound_speed") + ": not given: c = " + rule + " = " + number_text(cs) + " m/s");
  } else if (need_c) {
    MapReader eos = fluid.section("eos", {"type", "sound_speed", "gamma", "background_pressure", "clamp_negative"});
    if (!known)
      eos.fail_missing("sound_speed", "artificial speed of sound c in m/s, > 0 (case '" + c.case_name +
                                          "' gives no velocity scale to derive c = 10 U from)");
    c.fluid.eos.sound_speed = 10.0 * U;
    c.notices.push_back(eos.where("sound_speed") + ": not given: c = 10 U = " + number_text(c.fluid.eos.sound_speed) +
                        " m/s from the scene's velocity scale U = " + number_text(U) + " m/s");
  }
  if (need_u) {
    MapReader sh = disc.section("particle_shifting", {"enabled", "coefficient", "velocity", "correction"});
    if (!known)
      sh.fail_missing("velocity", "U in m/s, > 0 (case '" + c.case_name + "' gives no velocity scale)");
    ps.velocity = U;
  }
}

void set_position_correction(DiscretizationConfig& d, const std::string& scheme, std::string reason) {
  d.position_correction.chosen = scheme;
  d.position_correction.reason = std::move(reason);
  d.transport_velocity.enabled = scheme == "transport_velocity";
  d.particle_shifting.enabled = scheme == "particle_shifting";
}

// Selects the position correction from discretization.position_correction and the `enabled` the two
// maps state (tv_on, ps_on; nullopt where not stated). Explicit settings win over auto; a combination
// that selects two things, or contradicts the selection, is an error at the key that contradicts.
// Returns false when auto is left to the cell-Reynolds rule (resolve_position_correction).
bool select_position_correction(DiscretizationConfig& d, std::optional<bool> tv_on, std::optional<bool> ps_on,
                                MapReader& disc) {
  auto& pc = d.position_correction;
  const auto fail_enabled = [&](const std::string& map, bool on, const std::string& why) {
    const std::vector<std::string> keys = map == "transport_velocity"
                                              ? std::vector<std::string>{"enabled", "background_pressure", "step_factor", "extra_stress"}
                                              : std::vector<std::string>{"enabled", "coefficient", "velocity", "correction"};
    disc.section(map, keys).fail("enabled", std::string(on ? "true " : "false ") + why);
  };
  const std::string other_tv = "transport_velocity", other_ps = "particle_shifting";
  if (pc.setting.empty()) {  // the maps select, as before position_correction existed (both: check_position_correction)
    pc.chosen = d.transport_velocity.enabled ? other_tv : d.particle_shifting.enabled ? other_ps : "none";
    return true;
  }
  const std::string said = "conflicts with discretization.position_correction: " + pc.setting;
  if (pc.setting == "none") {
    if (tv_on == true) fail_enabled("transport_velocity", true, said);
    if (ps_on == true) fail_enabled("particle_shifting", true, said);
    set_position_correction(d, "none", "");
    return true;
  }
  if (pc.setting == other_tv || pc.setting == other_ps) {
    const bool tv = pc.setting == other_tv;
    if ((tv ? tv_on : ps_on) == false) fail_enabled(tv ? "transport_velocity" : "particle_shifting", false, said);
    if ((tv ? ps_on : tv_on) == true)
      fail_enabled(tv ? "particle_shifting" : "transport_velocity", true, said + " (the two are alternatives)");
    set_position_correction(d, pc.setting, "");
    return true;
  }
  // auto: an `enabled` a map states is an explicit choice and wins over the rule.
  if (tv_on == true && ps_on == true)
    fail_enabled("particle_shifting", true, "together with discretization.transport_velocity.enabled: true: the two are "
                                            "alternatives, give one of the two (or neither, for position_correction: auto)");
  if (tv_on == false && ps_on == false)
    disc.fail("position_correction", "auto has nothing to choose from: transport_velocity and particle_shifting both say "
                                     "enabled: false (use position_correction: none)");
  if (tv_on == true) set_position_correction(d, other_tv, "discretization.transport_velocity.enabled: true was given");
  else if (ps_on == true) set_position_correction(d, other_ps, "discretization.particle_shifting.enabled: true was given");
  else if (tv_on == false) set_position_correction(d, other_ps, "discretization.transport_velocity.enabled: false was given");
  else if (ps_on == false) set_position_correction(d, other_tv, "discretization.particle_shifting.enabled: false was given");
  else {
    // Neither on until the rule has chosen: nothing read before then may see a map as switched on.
    d.transport_velocity.enabled = d.particle_shifting.enabled = false;
    return false;
  }
  return true;
}

// What the chosen correction needs of the flow. The messages name the key that selected it.
void check_position_correction(Config& c, const CaseModule& module, MapReader& disc) {
  const auto& d = c.discretization;
  const auto& pc = d.position_correction;
  const bool by_key = !pc.setting.empty();
  const std::string via = pc.setting == "auto" ? " (position_correction: auto chose it: " + pc.reason + ")" : "";
  // Its background pressure would pull a free surface inward, and it needs one constant c.
  if (d.transport_velocity.enabled && (module.free_surface || c.fluid.eos.type == "ideal_gas"))
    disc.fail(by_key ? "position_correction" : "transport_velocity",
              std::string(by_key ? "'" + pc.setting + "': the transport velocity " : "") +
                  "needs a confined liquid with a constant sound speed (no free surface, not ideal_gas); case '" +
                  c.case_name + "' has " + (module.free_surface ? "a free surface" : "a gas") + via);
  // Grad C does not vanish at a free surface, so the shift would pull the surface particles inward.
  if (d.particle_shifting.enabled && module.free_surface)
    disc.fail(by_key ? "position_correction" : "particle_shifting",
              std::string(by_key ? "'" + pc.setting + "': particle shifting " : "") +
                  "needs a flow without a free surface; case '" + c.case_name + "' has one" + via);
  if (d.particle_shifting.enabled && d.transport_velocity.enabled)  // only the maps, without position_correction
    disc.fail("particle_shifting", "is an alternative to discretization.transport_velocity: give one of the two");
  // Parameters given for the scheme position_correction did not choose (with auto: "when chosen").
  if (!pc.setting.empty()) {
    const std::pair<const char*, std::vector<std::string>> maps[] = {
        {"transport_velocity", {"background_pressure", "step_factor", "extra_stress"}},
        {"particle_shifting", {"coefficient", "velocity", "correction"}}};
    for (const auto& [map, keys] : maps) {
      if (pc.chosen == map || !disc.has(map)) continue;
      std::vector<std::string> all = keys;  // (no lambda: clang 14 cannot capture a structured binding)
      all.push_back("enabled");
      MapReader m = disc.section(map, all);
      for (const auto& key : keys)
        if (m.has(key)) {
          c.notices.push_back(m.where(key) + ": not used: position_correction " + pc.setting +
                              (pc.setting == "auto" ? " chose " + pc.chosen + (pc.reason.empty() ? "" : " (" + pc.reason + ")") : ""));
          break;
        }
    }
  }
}

// position_correction: auto left to the rule: the transport velocity below the cell Reynolds number
// kPositionCorrectionCellReynolds, particle shifting at or above it (config/position_correction.hpp),
// with Re_h = U h / nu from the velocity scale that also gives c = 10 U and h = smoothing_ratio dx of
// the scene's spacing. Reports the choice as a notice.
void resolve_position_correction(Config& c, const CaseModule& module, MapReader& disc, double spacing) {
  auto& d = c.discretization;
  auto& pc = d.position_correction;
  if (pc.setting != "auto" || !pc.reason.empty()) return;
  const double U = config_velocity_scale(c, module);
  if (!(U > 0.0))
    disc.fail("position_correction", "auto chooses by the cell Reynolds number U h / nu, and case '" + c.case_name +
                                         "' gives no velocity scale U from its config (choose transport_velocity, "
                                         "particle_shifting or none)");
  const double h = d.smoothing_ratio * spacing, nu = c.fluid.kinematic_viscosity;
  pc.cell_reynolds = cell_reynolds_number(U, h, nu);
  const std::string scheme = position_correction_for(pc.cell_reynolds);
  set_position_correction(d, scheme,
                          "Re_h = U h / nu = " + number_text(U) + " * " + number_text(h) + " / " + number_text(nu) + " = " +
                              number_text(pc.cell_reynolds) + (scheme == "transport_velocity" ? " < " : " >= ") +
                              number_text(kPositionCorrectionCellReynolds));
  check_position_correction(c, module, disc);
}

Config validate(const YAML::Node& root, const YamlOrigin& origin) {
  Config c;
  c.source = origin.file();
  YAML::Mark root_mark = root.Mark();
  if (root_mark.line < 0) root_mark = YAML::Mark();  // empty document: point at line 1
  // The shared sections, and every section some case module owns; once the case is known, only
  // its own sections are allowed.
  const std::vector<std::string> shared = {"case", "dimension", "fluid", "discretization", "time", "output", "health", "probes"};
  std::vector<std::string> all_keys = shared;
  for (const auto& m : case_modules())
    for (const auto& k : m.sections)
      if (std::find(all_keys.begin(), all_keys.end(), k) == all_keys.end()) all_keys.push_back(k);
  MapReader top(origin, root, "", root_mark, all_keys);

  const auto names = case_names();
  c.case_name = top.choice("case", top.required(top.string("case"), "case", "one of: " + join(names)), names);
  const CaseModule& module = *find_case_module(c.case_name);
  {
    std::vector<std::string> own = shared;
    own.insert(own.end(), module.sections.begin(), module.sections.end());
    for (const auto& k : top.keys_present())
      if (std::find(own.begin(), own.end(), k) == own.end())
        top.fail(k, "is not used by case '" + c.case_name + "'" +
                        (module.sections.empty() ? std::string(" (it has no sections of its own)")
                                                 : " (its own sections: " + join(module.sections) + ")"));
  }
  if (module.defaults) module.defaults(c);
  if (const auto d = top.integer("dimension")) {
    top.check("dimension", *d >= 1 && *d <= 3, static_cast<double>(*d), "1, 2 or 3");
    c.dimension = static_cast<int>(*d);
  }
  if (!module.supports(c.dimension))
    top.fail("dimension", "case '" + c.case_name + "' needs dimension " + module.dimensions_text() + " (got " +
                              std::to_string(c.dimension) + ")");

  // fluid
  MapReader fluid = top.section("fluid", {"density", "kinematic_viscosity", "eos", "body_force", "body_force_ramp"});
  if (!module.uses_fluid_density && fluid.has("density"))
    fluid.fail("density", "is not used by case '" + c.case_name + "' (its initial states give the densities)");
  if (module.uses_fluid_density) {
    c.fluid.density = fluid.required(fluid.real("density"), "density", "reference density rho0 in kg/m^3, > 0");
    fluid.check("density", c.fluid.density > 0, c.fluid.density, "> 0 kg/m^3");
  }
  c.fluid.kinematic_viscosity = fluid.required(fluid.real("kinematic_viscosity"), "kinematic_viscosity",
                                               "nu in m^2/s, >= 0");
  fluid.check("kinematic_viscosity", c.fluid.kinematic_viscosity >= 0, c.fluid.kinematic_viscosity,
        ">= 0 m^2/s");
  {
    MapReader eos = fluid.section("eos", {"type", "sound_speed", "gamma", "background_pressure", "clamp_negative"});
    if (const auto t = eos.string("type"))
      c.fluid.eos.type = eos.choice("type", *t, {"linear", "linear_relative", "tait", "ideal_gas"});
    if (const auto v = eos.boolean("clamp_negative")) {
      if (c.fluid.eos.type != "tait") eos.fail("clamp_negative", "applies to type: tait only");
      c.fluid.eos.clamp_negative = *v;
    }
    if (const auto v = eos.real("background_pressure")) c.fluid.eos.background_pressure = *v;
    eos.check("background_pressure", c.fluid.eos.background_pressure >= 0, c.fluid.eos.background_pressure, ">= 0 Pa");
    if (c.fluid.eos.type == "ideal_gas") {
      if (eos.has("sound_speed"))
        eos.fail("sound_speed", "is not used with type 'ideal_gas' (c = sqrt(gamma p / rho) per particle)");
      c.fluid.eos.gamma = 1.4;
      if (const auto g = eos.real("gamma")) c.fluid.eos.gamma = *g;
      eos.check("gamma", c.fluid.eos.gamma > 1, c.fluid.eos.gamma, "> 1");
    } else {
    if (c.fluid.eos.type == "tait") {
      if (const auto g = eos.real("gamma")) c.fluid.eos.gamma = *g;
      eos.check("gamma", c.fluid.eos.gamma > 0, c.fluid.eos.gamma, "> 0");
    } else if (eos.has("gamma")) {
      eos.fail("gamma", "is used only with type 'tait' or 'ideal_gas' (got type '" + c.fluid.eos.type + "')");
    }
    // Absent: 10 U from the case's velocity scale, once the case's sections are read (below).
    if (const auto v = eos.real("sound_speed")) {
      c.fluid.eos.sound_speed = *v;
      eos.check("sound_speed", c.fluid.eos.sound_speed > 0, c.fluid.eos.sound_speed, "> 0 m/s");
    }
    }
  }
  if (const auto f = fluid.reals("body_force")) {
    if (static_cast<int>(f->size()) != c.dimension)
      fluid.fail("body_force", "has " + std::to_string(f->size()) + " components, expected " +
                                   std::to_string(c.dimension) + " (one per dimension)");
    c.fluid.body_force = *f;
  } else {
    c.fluid.body_force.assign(static_cast<std::size_t>(c.dimension), 0.0);
  }
  if (const auto v = fluid.real("body_force_ramp")) c.fluid.body_force_ramp = *v;
  fluid.check("body_force_ramp", c.fluid.body_force_ramp >= 0, c.fluid.body_force_ramp, ">= 0 s; 0 = at once");
  if (c.fluid.body_force_ramp > 0.0 && std::all_of(c.fluid.body_force.begin(), c.fluid.body_force.end(), [](double g) { return g == 0.0; }))
    c.notices.push_back(fluid.where("body_force_ramp") + ": has no effect: fluid.body_force is zero");

  // discretization
  MapReader disc = top.section("discretization",
                               {"particles_across", "spacing", "kernel", "smoothing_ratio", "density",
                                "momentum", "viscosity", "laplacian_correction", "xsph", "boundary", "wall_model", "wall_beta_max", "wall_layers",
                                "neighbor_search", "skin", "reorder", "pair_passes", "combine_terms", "wall_slip", "wall_pressure",
                                "wall_density_floor_width", "repulsive",
                                "artificial_viscosity", "artificial_conductivity", "energy", "smoothing_length", "transport_velocity", "particle_shifting", "position_correction",
                                "position_noise", "density_diffusion", "density_diffusion_form", "bulk_viscosity", "continuity", "particle_mass"});
  {
    auto& d = c.discretization;
    const auto n = disc.integer("particles_across");
    const auto dx = disc.real("spacing");
    if (n && dx)
      disc.fail("spacing", "both particles_across and spacing are given (allowed: exactly one of them)");
    if (!n && !dx && !module.spacing_from_scene)
      disc.fail_missing("particles_across", "or discretization.spacing: give exactly one of the two");
    if (n) {
      disc.check("particles_across", *n > 0, static_cast<double>(*n), "> 0");
      // Guards the int conversion; no real run comes near.
      disc.check("particles_across", *n <= 1'000'000'000, static_cast<double>(*n), "<= 1e9");
      d.particles_across = static_cast<int>(*n);
    } else if (dx) {
      disc.check("spacing", *dx > 0, *dx, "> 0 m");
      d.spacing = *dx;
    }  // else the case derives the spacing from its geometry (after its reader, below)
    if (const auto k = disc.string("kernel")) d.kernel = *k;
    const double support = c.dimension == 1   ? check_kernel<1>(disc, d.kernel)
                           : c.dimension == 2 ? check_kernel<2>(disc, d.kernel)
                                              : check_kernel<3>(disc, d.kernel);
    if (const auto v = disc.real("smoothing_ratio")) d.smoothing_ratio = *v;
    disc.check("smoothing_ratio", d.smoothing_ratio > 0, d.smoothing_ratio, "> 0 (h / dx)");
    // A support that does not reach the nearest lattice neighbour (one spacing away) leaves every
    // particle alone in its sums: no pressure force, the densities of isolated particles.
    if (!(support * d.smoothing_ratio > 1.0))
      disc.fail("smoothing_ratio", number_text(d.smoothing_ratio) + " gives " + d.kernel + " a support of " +
                                       number_text(support * d.smoothing_ratio) +
                                       " spacings, which does not reach the nearest particle one spacing away; it needs h / dx > " +
                                       number_text(1.0 / support));
    if (const auto v = disc.string("density")) d.density = disc.choice("density", *v, {"summation", "normalised_summation", "continuity"});
    if (const auto v = disc.string("momentum")) d.momentum = disc.choice("momentum", *v, {"symmetric_117", "symmetric_116", "integral_approach"});
    if (const auto v = disc.string("viscosity"))
      d.viscosity = disc.choice("viscosity", *v, {"strain_rate", "morris", "none"});
    if (const auto v = disc.real("xsph")) d.xsph = *v;
    disc.check("xsph", d.xsph >= 0 && d.xsph <= 1, d.xsph, "[0, 1]; 0 = off");
    if (const auto v = disc.real("position_noise")) {
      d.position_noise = *v;
      disc.check("position_noise", d.position_noise >= 0 && d.position_noise <= 0.25, d.position_noise,
            "[0, 0.25] particle spacings; 0 = off");
      if (d.position_noise > 0 && !module.position_noise)
        disc.fail("position_noise", "is not applied by case '" + c.case_name + "' (its scene is built without noise)");
    }
    if (const auto v = disc.string("boundary"))
      d.boundary = disc.choice("boundary", *v, {"wall_particles", "ghost", "virtual_repulsive"});
    if (const auto v = disc.string("wall_model")) d.wall_model = disc.choice("wall_model", *v, {"prescribed", "morris", "adami"});
    // Combinations that mean nothing are errors, not silently ignored keys.
    if (d.boundary != "wall_particles") {
      if (disc.has("wall_model") && d.wall_model != "prescribed")
        disc.fail("wall_model", d.wall_model + " extrapolates through wall particles; boundary '" + d.boundary +
                                    "' has none (ghost velocities already carry the wall condition)");
      d.wall_model = "prescribed";
    }
    if (const auto v = disc.string("wall_slip")) {
      if (d.boundary != "ghost") disc.fail("wall_slip", "applies to boundary: ghost only");
      d.wall_slip = disc.choice("wall_slip", *v, {"no_slip", "free_slip"});
      // The no-slip images' velocity enters the viscous terms only (boundary/ghost_particles.hpp).
      if (d.wall_slip == "no_slip" && d.viscosity == "none")
        c.notices.push_back(disc.where("wall_slip") + ": no_slip has no effect: it sets the ghost images' velocity in the "
                            "viscous terms, and discretization.viscosity is 'none' (every other term sees free-slip images)");
    }
    if (const auto v = disc.string("wall_pressure")) {
      d.wall_pressure = disc.choice("wall_pressure", *v, {"rest", "extrapolated", "dynamic"});
      if (d.wall_pressure != "rest" && d.boundary != "wall_particles")
        disc.fail("wall_pressure", "applies to boundary: wall_particles only");
    }
    // Adami et al. (2012) is one boundary: no-slip wall velocities and the extrapolated wall pressure.
    if (d.wall_model == "adami") {
      if (disc.has("wall_pressure") && d.wall_pressure != "extrapolated")
        disc.fail("wall_pressure", "wall_model: adami extrapolates the wall pressure (Adami et al. 2012); '" +
                                       d.wall_pressure + "' would replace it (use wall_model: morris or prescribed)");
      d.wall_pressure = "extrapolated";
      if (d.viscosity == "strain_rate")
        disc.fail("wall_model", "adami's no-slip wall velocity enters viscosity: morris (or none); viscosity: strain_rate "
                                "takes the wall velocity per pair from wall_model: morris or prescribed");
    }
    if (disc.has("repulsive") && d.boundary != "virtual_repulsive")
      disc.fail("repulsive", "parameters of Niedoba 2012, eq 2.76 apply to boundary: virtual_repulsive only");
    if (d.boundary == "virtual_repulsive") {
      MapReader rep = disc.section("repulsive", {"strength", "p1", "p2", "r0"});
      auto& r = d.repulsive;
      r.strength = rep.required(rep.real("strength"), "strength", "D of Niedoba 2012, eq 2.76 in m^2/s^2, > 0");
      rep.check("strength", r.strength > 0, r.strength, "> 0 m^2/s^2");
      if (const auto v = rep.real("p1")) r.p1 = *v;
      if (const auto v = rep.real("p2")) r.p2 = *v;
      if (const auto v = rep.real("r0")) r.r0 = *v;
      rep.check("p2", r.p2 > 0, r.p2, "> 0");
      rep.check("p1", r.p1 > r.p2, r.p1, "> p2 (repulsive inside r0)");
      rep.check("r0", r.r0 > 0, r.r0, "> 0 (particle spacings)");
    }
    if (const auto v = disc.string("laplacian_correction")) {
      d.laplacian_correction = disc.choice("laplacian_correction", *v, {"none", "moment", "moment_symmetric"});
      if (d.laplacian_correction != "none" && d.viscosity != "morris")
        disc.fail("laplacian_correction", "corrects the Morris viscosity only (discretization.viscosity is '" + d.viscosity + "')");
    }
    if (const auto v = disc.real("wall_beta_max")) d.wall_beta_max = *v;
    disc.check("wall_beta_max", d.wall_beta_max >= 1, d.wall_beta_max, ">= 1");
    // A value other than the default (config/defaults.yaml lists every key with its default).
    if (disc.has("wall_beta_max") && d.wall_beta_max != DiscretizationConfig{}.wall_beta_max && d.wall_model != "morris")
      c.notices.push_back(disc.where("wall_beta_max") + ": has no effect: it caps the extrapolation of wall_model: morris (wall_model is '" +
                          d.wall_model + "')");
    if (const auto v = disc.integer("wall_layers")) {
      disc.check("wall_layers", *v >= 0, static_cast<double>(*v), ">= 0; 0 = fill the kernel support");
      disc.check("wall_layers", *v <= 1000, static_cast<double>(*v), "<= 1000");
      d.wall_layers = static_cast<int>(*v);
    }
    if (const auto v = disc.string("neighbor_search"))
      d.neighbor_search = disc.choice("neighbor_search", *v, {"kdtree", "cell_list", "all_pairs"});
    if (const auto v = disc.real("skin")) d.skin = *v;
    disc.check("skin", d.skin >= 0, d.skin, ">= 0 (in units of h)");
    if (const auto v = disc.boolean("reorder")) d.reorder = *v;
    if (const auto v = disc.boolean("combine_terms")) d.combine_terms = *v;
    if (const auto v = disc.string("pair_passes")) d.pair_passes = disc.choice("pair_passes", *v, {"auto", "fused", "stored"});
    if (d.reorder && d.boundary == "ghost")
      disc.fail("reorder", "not available with boundary 'ghost' (mirror images refer to the previous particle order)");
    if (disc.has("artificial_viscosity")) {
      MapReader av = disc.section("artificial_viscosity", {"form", "alpha", "beta", "eta", "switch", "switch_width", "switch_offset"});
      auto& a = d.artificial_viscosity;
      a.enabled = true;
      if (const auto v = av.string("form")) a.form = av.choice("form", *v, {"monaghan_1992", "monaghan_1997"});
      if (a.form == "monaghan_1997") {
        a.beta = 2.0;  // Price 2008: v_sig = (c_i + c_j - 2 w_ij)/2
        if (av.has("eta")) av.fail("eta", "is used by form 'monaghan_1992' only (the signal-velocity form has no eta)");
      }
      if (const auto v = av.real("alpha")) a.alpha = *v;
      av.check("alpha", a.alpha >= 0, a.alpha, ">= 0");
      if (const auto v = av.real("beta")) a.beta = *v;
      av.check("beta", a.beta >= 0, a.beta, ">= 0");
      if (const auto v = av.real("eta")) a.eta = *v;
      av.check("eta", a.eta > 0, a.eta, "> 0 (eta / h_ij)");
      if (const auto v = av.string("switch")) a.switch_form = av.choice("switch", *v, {"smooth", "sharp"});
      if (a.switch_form == "sharp" && av.has("switch_width"))
        av.fail("switch_width", "is the band of switch 'smooth' only (switch: sharp is min(v_ij.x_ij, 0))");
      if (const auto v = av.real("switch_width")) a.switch_width = *v;
      av.check("switch_width", a.switch_width > 0 && a.switch_width <= 1, a.switch_width,
               "in (0, 1] (the band in cbar_ij h_ij)");
      if (a.switch_form == "sharp" && av.has("switch_offset"))
        av.fail("switch_offset", "places the band of switch 'smooth' only (switch: sharp is min(v_ij.x_ij, 0))");
      if (const auto v = av.real("switch_offset")) a.switch_offset = *v;
      av.check("switch_offset", a.switch_offset >= 0 && a.switch_offset <= 0.5, a.switch_offset,
               "in [0, 0.5] (the band's receding part, a fraction of it)");
    }
    if (disc.has("artificial_conductivity")) {
      MapReader ac = disc.section("artificial_conductivity", {"alpha"});
      auto& a = d.artificial_conductivity;
      a.enabled = true;
      if (const auto v = ac.real("alpha")) a.alpha = *v;
      ac.check("alpha", a.alpha >= 0, a.alpha, ">= 0");
    }
    // The position correction: the transport velocity or particle shifting (or neither). Without
    // discretization.position_correction the maps select, as they always did; with it, it selects and
    // the maps hold the parameters (select_position_correction). Read here, checked once chosen.
    std::optional<bool> tv_on, ps_on;  // `enabled` as the maps state it (nullopt: not stated)
    if (const auto v = disc.string("position_correction"))
      d.position_correction.setting =
          disc.choice("position_correction", *v, {"auto", "transport_velocity", "particle_shifting", "none"});
    if (disc.has("transport_velocity")) {
      MapReader tv = disc.section("transport_velocity", {"enabled", "background_pressure", "step_factor", "extra_stress"});
      auto& t = d.transport_velocity;
      tv_on = tv.boolean("enabled");
      t.enabled = tv_on.value_or(true);
      if (const auto v = tv.real("background_pressure")) t.background_pressure = *v;
      tv.check("background_pressure", t.background_pressure >= 0, t.background_pressure, ">= 0 Pa; 0 = rho0 c^2");
      if (const auto v = tv.real("step_factor")) t.step_factor = *v;
      tv.check("step_factor", t.step_factor > 0, t.step_factor, "> 0 (tau = step_factor h / c)");
      if (const auto v = tv.boolean("extra_stress")) t.extra_stress = *v;
    }
    if (disc.has("particle_shifting")) {
      MapReader sh = disc.section("particle_shifting", {"enabled", "coefficient", "velocity", "correction"});
      auto& p = d.particle_shifting;
      ps_on = sh.boolean("enabled");
      p.enabled = ps_on.value_or(true);
      if (const auto v = sh.real("coefficient")) p.coefficient = *v;
      sh.check("coefficient", p.coefficient > 0, p.coefficient, "> 0 (du = -A h U grad C)");
      if (const auto v = sh.real("velocity")) {
        p.velocity = *v;
        sh.check("velocity", p.velocity > 0, p.velocity, "> 0 m/s; absent = the scene's velocity scale");
      }
      if (const auto v = sh.boolean("correction")) p.correction = *v;
    }
    // auto by the rule waits for the scene's spacing (resolve_position_correction, after the case).
    if (select_position_correction(d, tv_on, ps_on, disc)) check_position_correction(c, module, disc);
    if (const auto v = disc.boolean("energy")) d.energy = *v;
    if (d.energy && !module.provides_energy)
      disc.fail("energy", "case '" + c.case_name + "' provides no initial internal energy for the energy equation");
    if (const auto v = disc.string("smoothing_length"))
      d.smoothing_length = disc.choice("smoothing_length", *v, {"constant", "density", "ode"});
    // Combinations that have no meaning, named by both keys.
    if (d.artificial_conductivity.enabled && !d.energy)
      disc.fail("artificial_conductivity", "conducts internal energy; needs discretization.energy: true");
    if (c.fluid.eos.type == "ideal_gas" && !d.energy)
      disc.fail("energy", "fluid.eos.type 'ideal_gas' needs discretization.energy: true (p = (gamma - 1) rho e)");
    if (d.energy && c.fluid.kinematic_viscosity != 0)
      disc.fail("energy", "the energy equation covers inviscid flow only (viscous heating is not implemented); "
                          "fluid.kinematic_viscosity must be 0 (got " + number_text(c.fluid.kinematic_viscosity) + ")");
    if (d.viscosity == "none" && c.fluid.kinematic_viscosity != 0)
      disc.fail("viscosity", "'none' with fluid.kinematic_viscosity = " + number_text(c.fluid.kinematic_viscosity) +
                                 " (a viscous fluid needs 'morris' or 'strain_rate')");
    if (d.smoothing_length != "constant" && d.density != "continuity")
      disc.fail("smoothing_length", "'" + d.smoothing_length + "' needs discretization.density: continuity (got '" +
                                        d.density + "'): a summation density would depend on h implicitly");
    if (const auto v = disc.real("density_diffusion")) d.density_diffusion = *v;
    disc.check("density_diffusion", d.density_diffusion >= 0, d.density_diffusion, ">= 0 (delta; 0 = off)");
    if (d.density_diffusion > 0 && d.density != "continuity")
      disc.fail("density_diffusion", "diffuses the continuity density; needs discretization.density: continuity (got '" +
                                         d.density + "')");
    if (const auto v = disc.string("density_diffusion_form"))
      d.density_diffusion_form = disc.choice("density_diffusion_form", *v, {"molteni_colagrossi", "hydrostatic_corrected"});
    // A form without the diffusion is said, not refused: turning the diffusion off in a file that names
    // the form is `--set discretization.density_diffusion=0` alone.
    if (d.density_diffusion_form != "molteni_colagrossi" && !(d.density_diffusion > 0))
      c.notices.push_back(disc.where("density_diffusion_form") + ": '" + d.density_diffusion_form +
                          "' has no effect: discretization.density_diffusion is 0 (off)");
    if (const auto v = disc.real("bulk_viscosity")) d.bulk_viscosity = *v;
    disc.check("bulk_viscosity", d.bulk_viscosity >= 0 && d.bulk_viscosity <= 100, d.bulk_viscosity, "in [0, 100] (zeta / (c0 h); 0 = off)");
    if (d.bulk_viscosity > 0 && d.boundary == "ghost")
      disc.fail("bulk_viscosity", "not available with boundary 'ghost': the images carry the mirrored no-slip velocity, whose "
                                  "divergence is not the fluid's (use boundary: wall_particles)");
    if (d.bulk_viscosity > 0 && c.fluid.eos.type == "ideal_gas")
      disc.fail("bulk_viscosity", "is scaled by the constant sound speed c0 of a liquid's equation of state; an ideal gas "
                                  "has none (use discretization.artificial_viscosity)");
    if (const auto v = disc.string("continuity")) d.continuity = disc.choice("continuity", *v, {"mass", "volume"});
    if (d.continuity != "mass" && d.density != "continuity")
      disc.fail("continuity", "'" + d.continuity + "' weights the continuity density; needs discretization.density: "
                              "continuity (got '" + d.density + "')");
    if (const auto v = disc.string("particle_mass")) {
      d.particle_mass = disc.choice("particle_mass", *v, {"summation", "gradient"});
      if (d.particle_mass != "summation" && !module.lattice_mass)
        disc.fail("particle_mass", "is not applied by case '" + c.case_name + "' (its scene sets its own particle masses)");
      // Summation density takes rho from the masses: only the summation mass gives rho0 on the lattice.
      if (d.particle_mass == "gradient" && d.density != "continuity")
        disc.fail("particle_mass", "'gradient' gives the lattice a summed density other than rho0; needs "
                                   "discretization.density: continuity (got '" + d.density + "')");
    }
    if (d.continuity != "mass" && d.wall_pressure == "dynamic")
      disc.fail("continuity", "'" + d.continuity + "' is for the fluid's density; dynamic wall particles (wall_pressure: "
                              "dynamic) evolve theirs by the mass-weighted sum: use continuity: mass");
    // That some wall is dynamic (this key, or a scene body's treatment) is checked when the walls are
    // built (rhs/assemble.cpp).
    if (const auto v = disc.real("wall_density_floor_width")) {
      d.wall_density_floor_width_given = true;
      d.wall_density_floor_width = *v;
    }
    disc.check("wall_density_floor_width", d.wall_density_floor_width >= 0 && d.wall_density_floor_width < 1,
               d.wall_density_floor_width, "in [0, 1) (units of fluid.density; 0 = max(rho_wall, rho0))");
    if (d.wall_pressure == "dynamic" && d.density != "continuity")
      disc.fail("wall_pressure", "'dynamic' evolves wall densities by continuity; needs discretization.density: "
                                 "continuity (got '" + d.density + "')");
    if (d.wall_pressure == "dynamic" && (c.fluid.eos.type == "ideal_gas" || d.smoothing_length != "constant"))
      disc.fail("wall_pressure", "'dynamic' needs a barotropic EOS and constant h");
    if (d.smoothing_length != "constant" && d.neighbor_search != "kdtree")
      disc.fail("smoothing_length", "'" + d.smoothing_length + "' needs discretization.neighbor_search: kdtree (got '" +
                                        d.neighbor_search + "')");
    if (disc.has("combine_terms") && !d.combine_terms && !d.has_combinable_terms())
      c.notices.push_back(disc.where("combine_terms") + ": has no effect: nothing to combine here (it merges continuity "
                          "density with continuity: mass, the symmetric_117 pressure gradient and, if any, monaghan_1992 "
                          "artificial viscosity, where there is no physical viscosity, energy equation or hydrostatic_corrected diffusion)");
  }

  // time
  std::string cfl_viscous_where;  // where time.cfl.viscous was given, for the notice after the case
  MapReader time = top.section("time", {"t_end", "integrator", "table", "rtol", "atol", "cfl", "dt", "max_steps", "krylov"});
  {
    auto& t = c.time;
    t.t_end = time.required(time.real("t_end"), "t_end", "end time in s, > 0");
    time.check("t_end", t.t_end > 0, t.t_end, "> 0 s");
    if (const auto v = time.string("integrator"))
      t.integrator = time.choice("integrator", *v, {"arkode_erk", "leapfrog", "leapfrog_kdk", "cvode_adams", "leapfrog_imex", "arkode_imex"});
    const bool imex = t.implicit_viscosity();
    if (imex) {
      // The implicit part is the Morris viscous sum, linear in the fluid velocities with the walls'
      // own (prescribed or Morris-extrapolated) velocities (time/viscous_operator.hpp).
      const auto& d = c.discretization;
      if (d.viscosity == "none")
        time.fail("integrator", "'" + t.integrator + "' treats the viscous term implicitly, and discretization.viscosity is 'none' "
                                "(nothing to treat implicitly; use leapfrog_kdk or arkode_erk)");
      if (d.viscosity != "morris")
        time.fail("integrator", "'" + t.integrator + "' needs discretization.viscosity: morris (got '" + d.viscosity + "')");
      if (d.wall_model == "adami")
        time.fail("integrator", "'" + t.integrator + "' needs discretization.wall_model: prescribed or morris (adami's wall "
                                "velocities depend on the fluid velocities)");
      if (d.boundary == "ghost")
        time.fail("integrator", "'" + t.integrator + "' does not support discretization.boundary: ghost (the images' "
                                "velocities depend on the fluid velocities)");
    }
    if (t.integrator == "arkode_imex") t.table = "ARKODE_ARK324L2SA_ERK_4_2_3";
    if (const auto v = time.string("table")) {
      if (t.integrator == "arkode_imex") {
        if (!ark_pair_of(*v)) {
          const std::string near = closest_match(*v, ark_pair_names());
          time.fail("table", "'" + *v + "' is not one table of a SUNDIALS ARK ImEx pair (" +
                                 (near.empty() ? "" : "did you mean '" + near + "'? ") + "pairs: " + join(ark_pair_names()) +
                                 ", or their _DIRK_ partners)");
        }
      } else if (!is_erk_table_name(*v)) {
        const std::string near = closest_match(*v, erk_table_names());
        time.fail("table", "'" + *v + "' is not a SUNDIALS explicit (ERK) Butcher table (" +
                               (near.empty() ? "" : "did you mean '" + near + "'? ") +
                               "see ARKODE_ERKTableID in arkode/arkode_butcher_erk.h, e.g. "
                               "ARKODE_DORMAND_PRINCE_7_4_5)");
      }
      t.table = *v;
    }
    if (const auto v = time.real("rtol")) {
      t.rtol = *v;
      t.rtol_given = true;
    }
    // Below a few units of round-off (2.2e-16) SUNDIALS refuses the step ("too much accuracy").
    time.check("rtol", t.rtol >= 1e-15, t.rtol, ">= 1e-15, the double round-off");
    if (const auto v = time.real("atol")) {
      t.atol = *v;
      t.atol_given = true;
    }
    time.check("atol", t.atol > 0, t.atol, "> 0");
    MapReader cfl = time.section("cfl", {"acoustic", "force", "viscous"});
    // Stability ranges of the explicit schemes (config/README.md, "CFL coefficients"): a larger
    // coefficient lets the integrator take steps past the limit of its own stability region.
    if (const auto v = cfl.real("acoustic")) t.cfl.acoustic = *v;
    cfl.check("acoustic", t.cfl.acoustic > 0 && t.cfl.acoustic <= CflConfig::kMaxAcoustic, t.cfl.acoustic,
          "(0, 1]: a sound wave may cross at most one smoothing length per step (Monaghan 1992 uses 0.25-0.4)");
    if (const auto v = cfl.real("force")) t.cfl.force = *v;
    cfl.check("force", t.cfl.force > 0 && t.cfl.force <= CflConfig::kMaxForce, t.cfl.force,
          "(0, 1]: the leapfrog is stable for omega dt < 2 with omega^2 ~ |a|/h; 1 keeps a factor 2 (Monaghan 1992 uses 0.25)");
    if (const auto v = cfl.real("viscous")) t.cfl.viscous = *v;
    cfl.check("viscous", t.cfl.viscous > 0 && t.cfl.viscous <= CflConfig::kMaxViscous, t.cfl.viscous,
          "(0, 0.125]: the explicit viscous step limit dt <= 0.125 h^2/nu of Morris, Fox & Zhu 1997; "
          "the leapfrog Couette flow diverges at 0.15");
    // Given at a value other than the default, which the resolved config.yaml writes for every run.
    if (cfl.has("viscous") && t.cfl.viscous != CflConfig{}.viscous) cfl_viscous_where = cfl.where("viscous");
    if (const auto v = time.real("dt")) {
      time.check("dt", *v > 0, *v, "> 0 s");
      if (t.integrator == "cvode_adams")
        time.fail("dt", "cvode_adams is adaptive only (rtol/atol, step bounded by the CFL limit); remove time.dt");
      t.dt = *v;
    }
    // Given settings the integrator does not read: a notice, not an error (a config written for
    // another integrator, or by an earlier sph-mol, still loads).
    const auto unused = [&](const std::string& key, const std::string& why) {
      if (time.has(key)) c.notices.push_back(time.where(key) + ": has no effect: " + why);
    };
    if (!t.takes_table()) unused("table", t.integrator + " takes no Butcher table (arkode_erk and arkode_imex do)");
    const std::string no_tolerances =
        t.integrator == "arkode_erk" ? "arkode_erk with a fixed time.dt has no error control"
                                     : t.integrator + " takes fixed or CFL steps without error control "
                                                      "(rtol and atol are for arkode_erk, arkode_imex and cvode_adams)";
    if (!t.takes_tolerances()) {
      unused("rtol", no_tolerances);
      unused("atol", no_tolerances);
    }
    if (!t.takes_cfl()) unused("cfl", "a fixed time.dt is not bounded by the CFL limits (remove time.dt for CFL steps)");
    if (const auto v = time.integer("max_steps")) {
      time.check("max_steps", *v > 0, static_cast<double>(*v), "> 0");
      t.max_steps = static_cast<long>(*v);
    }
    MapReader krylov = time.section("krylov", {"solver", "tolerance", "max_iterations"});
    if (!imex && time.has("krylov"))
      time.fail("krylov", "applies to time.integrator: leapfrog_imex or arkode_imex (got '" + t.integrator + "')");
    // Default: conjugate gradients where the operator is symmetric, GMRES where rows are scaled apart.
    // moment_symmetric scales each pair by a factor symmetric in i and j: the operator stays symmetric.
    if (c.discretization.laplacian_correction == "moment") t.krylov.solver = "spgmr";
    if (const auto v = krylov.string("solver")) t.krylov.solver = krylov.choice("solver", *v, {"pcg", "spgmr"});
    if (krylov.has("solver") && t.krylov.solver == "pcg" && c.discretization.laplacian_correction == "moment")
      krylov.fail("solver", "'pcg' needs a symmetric operator; discretization.laplacian_correction: " +
                                c.discretization.laplacian_correction + " scales each row by its own moment (use spgmr)");
    if (const auto v = krylov.real("tolerance")) {
      if (t.integrator == "arkode_imex")
        krylov.fail("tolerance", "is for leapfrog_imex; arkode_imex derives its Krylov tolerance from time.rtol and time.atol");
      krylov.check("tolerance", *v > 0 && *v < 1, *v, "(0, 1): relative residual");
      t.krylov.tolerance = *v;
    }
    if (const auto v = krylov.integer("max_iterations")) {
      // GMRES keeps one vector of the velocities per iteration (at 1e6 particles in 3D, 24 MB each);
      // conjugate gradients keep a few. Jacobi-preconditioned viscous systems converge in tens of
      // iterations at the steps the IMEX integrators take, so these bounds only catch typing slips
      // (and keep the value an int).
      const bool gmres = t.krylov.solver == "spgmr";
      krylov.check("max_iterations", *v > 0 && *v <= (gmres ? 200 : 1000), static_cast<double>(*v),
                   gmres ? "1 to 200 with spgmr, which stores one vector per iteration" : "1 to 1000");
      t.krylov.max_iterations = static_cast<int>(*v);
    }
  }

  // output
  MapReader out = top.section("output", {"directory", "times", "profiles", "vtk", "vtk_walls", "vtk_ghosts", "plots",
                                         "checkpoint_every", "every"});
  {
    auto& o = c.output;
    if (const auto v = out.string("directory")) {
      if (trim(*v).empty()) out.fail("directory", "must not be empty");
      o.directory = *v;
    }
    if (const auto v = out.reals("times")) {
      for (std::size_t i = 0; i < v->size(); ++i) {
        if ((*v)[i] <= 0) out.fail_element("times", i, number_text((*v)[i]) + " is out of range (allowed: > 0 s)");
        if (i > 0 && (*v)[i] <= (*v)[i - 1])
          out.fail_element("times", i, number_text((*v)[i]) + " is not after the previous time " +
                                           number_text((*v)[i - 1]) + " (times must be strictly increasing)");
      }
      std::string dropped;
      std::size_t ndropped = 0;
      for (double x : *v) {
        if (x <= c.time.t_end) {
          o.times.push_back(x);
        } else {
          dropped += (dropped.empty() ? "" : ", ") + number_text(x);
          ++ndropped;
        }
      }
      if (ndropped > 0)
        c.notices.push_back(out.where("times") + ": dropped " + std::to_string(ndropped) +
                            " output time(s) past time.t_end = " + number_text(c.time.t_end) + ": " + dropped);
    }
    // --- output.every (an evenly spaced alternative to output.times) ---
    if (const auto v = out.real("every")) {
      // An empty list (--set output.times=[] to switch a file's list off) gives no times.
      if (out.has("times") && !out.reals("times")->empty()) out.fail("every", "give either output.times or output.every, not both");
      out.check("every", *v > 0, *v, "> 0 s");
      // Like output times past t_end (a file shortened with --set time.t_end): dropped, with a notice.
      if (*v > c.time.t_end)
        c.notices.push_back(out.where("every") + ": " + number_text(*v) + " s is past time.t_end = " + number_text(c.time.t_end) +
                            " s: the only output time is t_end");
      const double n = std::floor(c.time.t_end / *v * (1 + 1e-12));
      if (n > 1e6) out.fail("every", number_text(*v) + " s gives " + number_text(n) + " output times (at most 1e6)");
      // k * every rounds off: a time within 1e-9 every of t_end is t_end.
      for (long k = 1; k <= static_cast<long>(n) && k * *v < c.time.t_end - 1e-9 * *v; ++k) o.times.push_back(k * *v);
      o.every = *v;
    }
    // --- end output.every ---
    if (o.times.empty() || o.times.back() < c.time.t_end) o.times.push_back(c.time.t_end);
    // The files of an output time are named by its six significant digits (profile_t0.5.csv): two
    // times with one name would overwrite each other's files.
    std::string before = o.times.empty() ? std::string() : output_time_text(o.times[0]);
    for (std::size_t i = 1; i < o.times.size(); ++i) {
      std::string now = output_time_text(o.times[i]);
      if (now == before)
        out.fail(out.has("every") ? "every" : "times", "the output times " + number_text(o.times[i - 1]) + " and " +
                                                           number_text(o.times[i]) + " name the same files (t" + now +
                                                           "): output times must differ in their first six significant digits");
      before = std::move(now);
    }
    if (const auto v = out.boolean("profiles")) o.profiles = *v;
    if (const auto v = out.boolean("vtk")) o.vtk = *v;
    if (const auto v = out.boolean("vtk_walls")) o.vtk_walls = *v;
    if (out.has("vtk_walls") && o.vtk_walls != OutputConfig{}.vtk_walls && !o.vtk) c.notices.push_back(out.where("vtk_walls") + ": has no effect: output.vtk is false");
    if (const auto v = out.boolean("vtk_ghosts")) {
      o.vtk_ghosts = *v;
      if (o.vtk_ghosts && c.discretization.boundary != "ghost")
        out.fail("vtk_ghosts", "needs discretization.boundary: ghost (boundary '" + c.discretization.boundary +
                                   "' generates no ghost particles)");
      if (o.vtk_ghosts && !o.vtk) out.fail("vtk_ghosts", "needs output.vtk: true (it adds ghosts to the VTK files)");
    }
    if (const auto v = out.boolean("plots")) o.plots = *v;
    if (const auto v = out.real("checkpoint_every")) o.checkpoint_every = *v;
    out.check("checkpoint_every", o.checkpoint_every >= 0, o.checkpoint_every, ">= 0 s; 0 = no checkpoints");
  }
  // health (run/health_check.hpp, run/outflow.hpp)
  std::string outflow_where;  // where max_outflow_fraction was given, for the notice below
  {
    MapReader health = top.section("health", {"max_outflow_fraction"});
    auto& h = c.health;
    if (const auto v = health.real("max_outflow_fraction")) h.max_outflow_fraction = *v;
    // Given at a value other than the default, which config/defaults.yaml and the resolved config.yaml
    // write for every case.
    if (health.has("max_outflow_fraction") && h.max_outflow_fraction != HealthConfig{}.max_outflow_fraction)
      outflow_where = health.where("max_outflow_fraction");
    health.check("max_outflow_fraction", h.max_outflow_fraction >= 0 && h.max_outflow_fraction <= 1, h.max_outflow_fraction,
                 "in [0, 1]: the fraction of the fluid mass that may leave the domain; 0 = none");
  }
  CaseReaders readers{top, fluid, disc, time, out};
  CaseRead own = module.read(readers, c);
  c.case_settings = std::move(own.settings);
  c.notices.insert(c.notices.end(), own.notices.begin(), own.notices.end());
  // A value other than the default (0, fill the support), which config/defaults.yaml and the resolved
  // config.yaml write for every case.
  if (disc.has("wall_layers") && c.discretization.wall_layers != DiscretizationConfig{}.wall_layers && own.wall_count_known &&
      own.size.wall == 0.0)
    c.notices.push_back(disc.where("wall_layers") + ": has no effect: case '" + c.case_name + "' makes no wall particles here (" +
                        (c.discretization.boundary == "wall_particles" ? std::string("it has no walls")
                                                                       : "boundary '" + c.discretization.boundary + "'") + ")");
  // The viscous step limit binds only an explicit viscosity (rhs/sph_system.hpp, cfl_step).
  if (!cfl_viscous_where.empty() && c.time.takes_cfl()) {  // else the notice on time.cfl says it all
    const bool imex = c.time.implicit_viscosity();
    const double nu = std::max(c.fluid.kinematic_viscosity, own.size.kinematic_viscosity);
    if (CflConfig::diffusivity(imex ? 0.0 : nu, c.discretization.bulk_viscosity) == 0.0)
      c.notices.push_back(cfl_viscous_where + ": has no effect: " +
                          (imex && nu > 0.0 ? "'" + c.time.integrator + "' treats the viscosity implicitly and no bulk_viscosity is set, so "
                                              "no viscous step limit applies (it bounds the steps of the explicit integrators)"
                                            : std::string("the fluid is inviscid (kinematic_viscosity 0, no bulk_viscosity), so no "
                                                          "viscous step limit applies")));
  }
  if (!outflow_where.empty() && !own.open_to_outflow)
    c.notices.push_back(outflow_where + ": has no effect: case '" + c.case_name + "' has no face open to outflow (fluid "
                        "beyond a closed face or wall ends the run as blown up)");
  if (c.discretization.particles_across == 0 && !(c.discretization.spacing > 0.0)) {
    if (!(own.size.spacing > 0.0))
      disc.fail_missing("particles_across", "or discretization.spacing: case '" + c.case_name + "' derived no spacing");
    c.discretization.spacing = own.size.spacing;
    c.notices.push_back(disc.where("spacing") + ": not given: " + number_text(own.size.spacing) + " m (" + own.spacing_rule + ")");
  }
  resolve_position_correction(c, module, disc, own.size.spacing);
  if (c.discretization.position_correction.setting == "auto")
    c.notices.push_back(disc.where("position_correction") + ": auto: " + c.discretization.position_correction.chosen +
                        " (" + c.discretization.position_correction.reason + ")");
  resolve_velocity_defaults(c, module, fluid, disc);
  // Probes (probes/probe_config.hpp) after the case: a force probe names one of its wall bodies.
  c.probes = read_probes(top, c, c.case_settings->wall_bodies(), &c.notices);
  check_scene(c, readers, own.size);
  return c;
}

}  // namespace

Config load_config_string(const std::string& yaml, const std::vector<std::string>& overrides,
                          const std::string& name) {
  YAML::Node root = parse_yaml(yaml, name);
  YamlOrigin origin(name);
  for (const auto& o : overrides) apply_override(root, o, origin);
  return validate(root, origin);
}

Config load_config(const std::string& path, const std::vector<std::string>& overrides) {
  std::string text;
  try {
    text = read_input_file(path, kMaxConfigBytes, "config file");
  } catch (const InputFileError& e) {
    throw ConfigError(e.what());
  }
  return load_config_string(text, overrides, path);
}

}  // namespace sphmol
