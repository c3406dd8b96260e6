#pragma once
// The resolved, validated configuration of one run . Produced only by load_config(),
// which rejects unknown keys, wrong types, missing required values and non-physical values
// with a ConfigError naming the key, the file and the line. Every field here is used by the
// solver: nothing is parsed and then ignored.
#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sphmol/probes/probe_config.hpp"

namespace sphmol {

struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A case's own settings: the sections its module reads (cases/case_module.hpp), kept by Config and
// written back by to_yaml. Each case module derives its own.
struct CaseSettings {
  virtual ~CaseSettings() = default;
  // The sections as resolved YAML, top-level keys at column 0, every default filled in.
  virtual std::string to_yaml() const = 0;
  // The names of the scene's wall bodies, in body-index order (Particles::body), for force probes.
  virtual std::vector<std::string> wall_bodies() const { return {}; }
};

struct EosConfig {
  std::string type = "linear";  // "linear": p = c^2 rho (Morris, Vukčević et al. 2012, eq 20); "linear_relative": p = c^2 (rho - rho0)
  double sound_speed = 0.0;     // c [m/s], > 0; when not given, 10 U of the case's velocity scale (loader)
  double background_pressure = 0.0;  // [Pa] added to every particle's pressure after the EOS, >= 0
  bool clamp_negative = false;       // "tait": p = max(p, 0) (free surfaces with summation density)
  // "tait": p = B((rho/rho0)^gamma - 1), B = c^2 rho0 / gamma (Niedoba 2012, eq 2.75), gamma > 0, default 7.
  // "ideal_gas": p = (gamma - 1) rho e (Niedoba 2012, eq 2.73), gamma > 1, default 1.4; needs
  // discretization.energy: true and takes no sound_speed (c = sqrt(gamma p / rho) per particle).
  // The loader sets the default of the chosen type when gamma is not given.
  double gamma = 7.0;
};

struct FluidConfig {
  double density = 0.0;              // rho0 [kg/m^3], required, > 0
  double kinematic_viscosity = 0.0;  // nu [m^2/s], required, >= 0
  EosConfig eos;
  std::vector<double> body_force;    // [m/s^2], length = dimension; default (and if absent) all zero
  double body_force_ramp = 0.0;      // [s] body force ramped in smoothly over this time; 0 = at once
};

struct RepulsiveConfig {  // Niedoba 2012, eq 2.76, for boundary: virtual_repulsive
  double strength = 0.0;  // D [m^2/s^2], required there, > 0
  double p1 = 12.0;       // > p2
  double p2 = 4.0;        // > 0
  double r0 = 1.0;        // cut-off radius in particle spacings, > 0 and inside the kernel support
};

// Monaghan artificial viscosity; absent from the YAML = off. form: monaghan_1992 (Niedoba 2012,
// eq 2.70, theta_ij quadratic with eta) or monaghan_1997 (signal velocity, physics/artificial_viscosity.hpp).
struct ArtificialViscosityConfig {
  bool enabled = false;
  std::string form = "monaghan_1992";
  double alpha = 1.0;  // >= 0
  double beta = 1.0;   // >= 0 (monaghan_1997: default 2, Price 2008)
  double eta = 0.1;    // eta / h_ij, > 0 (monaghan_1992 only)
  // The approaching-pair switch min(v_ij.x_ij, 0): "smooth" (C^6, band switch_width cbar h_ij;
  // physics/artificial_viscosity.hpp) or "sharp" (the default: the smooth switch all but switches
  // the viscosity off for pairs slower than its band, which a scene near rest relies on for damping).
  std::string switch_form = "sharp";
  double switch_width = 1e-4;  // in (0, 1], smooth only
  // The band's part on the receding side (v_ij.x_ij > 0), a fraction of it in [0, 0.5], smooth only:
  // the band is [-(1 - switch_offset), switch_offset] switch_width cbar h_ij.
  double switch_offset = 0.0;
  // The band the Pi forms take (MonaghanPi::width): 0 for the sharp switch, min(v_ij.x_ij, 0) exactly.
  double band_width() const { return switch_form == "smooth" ? switch_width : 0.0; }
  double band_offset() const { return switch_form == "smooth" ? switch_offset : 0.0; }
};

// Artificial thermal conductivity (Price 2008; physics/artificial_conductivity.hpp); absent = off.
struct ArtificialConductivityConfig {
  bool enabled = false;
  double alpha = 1.0;  // alpha_u >= 0
};

// Transport-velocity formulation (Adami, Hu & Adams 2013; physics/transport_velocity.hpp); absent = off.
struct TransportVelocityConfig {
  bool enabled = false;              // true when the map is given, unless it says enabled: false
  double background_pressure = 0.0;  // p_b [Pa] on the particle positions only, >= 0; 0 = rho0 c^2
  double step_factor = 0.25;         // time scale of the shift du: tau = step_factor h / c, > 0 (0.25: Adami's step)
  bool extra_stress = true;          // the A = rho v (v~ - v) term in the momentum equation
};

// Fickian particle shifting (Lind et al. 2012; physics/particle_shifting.hpp); absent = off.
struct ParticleShiftingConfig {
  bool enabled = false;      // true when the map is given, unless it says enabled: false
  double coefficient = 4.0;  // A in du = -A h U grad C, > 0 (4: the delta+-SPH shift of Sun et al. 2017)
  double velocity = 0.0;     // U [m/s], > 0; the loader sets the scene's velocity scale when not given
  bool correction = true;    // Taylor correction of v (and of rho in the state) to the shifted positions
};

// discretization.position_correction: which of the two corrections above runs. Absent (setting ""):
// the maps select as they always did (a map given is on unless it says enabled: false). Given, it
// selects, and the maps hold only their parameters; an `enabled` they state must agree with it.
// "auto" picks by the cell Reynolds number Re_h = U h / nu (config/position_correction.hpp).
struct PositionCorrectionConfig {
  std::string setting;          // "" (absent) | auto | transport_velocity | particle_shifting | none
  std::string chosen = "none";  // what runs: transport_velocity | particle_shifting | none
  double cell_reynolds = -1.0;  // auto by the rule: Re_h = U h / nu it used (inf for nu = 0); else < 0
  std::string reason;           // auto: one line on why (the Re_h and the threshold, or the key that decided)
};

struct DiscretizationConfig {
  int particles_across = 0;         // fluid particles across the channel height (> 0); or spacing
  double spacing = 0.0;             // particle spacing dx [m]; exactly one of the two is given
  std::string kernel = "cubic_spline";
  double smoothing_ratio = 1.3;     // h / dx, > 0
  std::string density = "summation";             // summation | normalised_summation (Niedoba 2012, eq 2.58) | continuity (Niedoba 2012, eq 2.61)
  // density: continuity only: "mass" (Niedoba 2012, eq 2.61) or "volume" (rho_i sum_j m_j / rho_j ...,
  // Colagrossi & Landrini 2003), the weights of the continuity sum (physics/continuity_density.hpp).
  std::string continuity = "mass";
  // Mass of the start lattice's particles (scenes/lattice_mass.hpp): "summation" (the lattice's summed
  // density is rho0) or "gradient" (the symmetric pressure gradient of a linear field is exact on the
  // lattice; continuity density only, where the mass sets the volumes m / rho but not rho).
  std::string particle_mass = "summation";
  std::string momentum = "symmetric_117";          // symmetric_117 (Vukčević 2012, eq 117) | symmetric_116 (Vukčević 2012, eq 116)
  std::string viscosity = "morris";              // morris (Morris et al. 1997) | strain_rate (Vukčević 2012, eqs 117/122) | none (inviscid)
  // Morris viscosity only: "none", or "moment" (each row divided by its discrete second moment, which
  // makes the Laplacian exact for quadratic fields on a full support; physics/morris_viscosity.hpp).
  std::string laplacian_correction = "none";
  double xsph = 0.0;                // XSPH epsilon (Vukčević et al. 2012, eq 21), 0 <= eps <= 1; 0 = off
  double position_noise = 0.0;      // scenes that allow it: seeded random displacement of the initial lattice [spacings], [0, 0.25]
  std::string boundary = "wall_particles";        // wall_particles | ghost | virtual_repulsive
  std::string wall_slip = "no_slip";               // ghost: no_slip | free_slip (all walls)
  // wall_particles: "rest" (walls keep rest density and its EOS pressure) or "extrapolated" (Adami 2012
  // pressure from the fluid, with the body force; boundary/wall_pressure_extrapolated.hpp)
  // "dynamic": dynamic boundary particles (Crespo et al. 2007): wall densities in the ODE state,
  // evolved by continuity with the fluid, pressure from the EOS (boundary/dynamic_wall_density.hpp).
  std::string wall_pressure = "rest";
  // Width of the smooth (C^6) floor max(rho_wall, rho0) of dynamic wall particles, in units of rho0 (>= 0;
  // 0 = the plain max; rhs/sph_system.cpp).
  double wall_density_floor_width = 1e-4;
  bool wall_density_floor_width_given = false;  // for the check that some wall is dynamic (scenes: per body)
  double density_diffusion = 0.0;  // delta-SPH delta (Molteni & Colagrossi 2009), >= 0; 0 = off; needs continuity
  // What it diffuses: "molteni_colagrossi" the density, "hydrostatic_corrected" its departure from hydrostatics
  // under the body force (Fourtakas et al. 2019; physics/density_diffusion.hpp).
  std::string density_diffusion_form = "molteni_colagrossi";
  // Bulk viscosity zeta in units of c0 h (physics/bulk_viscosity.hpp), >= 0; 0 = off; needs a constant
  // sound speed (not ideal_gas).
  double bulk_viscosity = 0.0;
  double bulk_zeta(double c0, double h) const { return bulk_viscosity * c0 * h; }  // zeta [m^2/s]
  RepulsiveConfig repulsive;
  // Velocity the viscous terms see at wall particles: "prescribed" (the wall's own velocity) or
  // "morris" (Morris, Fox & Zhu 1997: the fluid velocity extrapolated through the wall, per pair).
  std::string wall_model = "morris";
  double wall_beta_max = 8.0;       // cap on the extrapolation factor, >= 1 (see boundary/morris_wall_velocity.hpp)
  int wall_layers = 0;              // 0 = enough layers to fill the kernel support
  std::string neighbor_search = "kdtree";         // kdtree | all_pairs
  double skin = 0.3;                // Verlet skin in units of h, >= 0
  bool reorder = false;             // Morton-order the workspace at each list rebuild (rhs/sph_system.hpp)
  // auto: fused pair passes (rhs/fused_pair_pass.hpp) when every pair term has a row form, else stored;
  // fused: required (error otherwise); stored: the active-pair list is built and kept per evaluation.
  std::string pair_passes = "auto";
  // Merge pair terms that meet in one scene into one pair loop (physics/weakly_compressible_row.hpp);
  // bit-identical, off only to measure the gain.
  bool combine_terms = true;
  // Whether the scene has the terms combine_terms merges: continuity density (mass form), optional
  // plain delta-SPH, the 117 pressure gradient and optional Monaghan 1992 viscosity, with no physical
  // viscosity and no energy equation (the dam break's formulation).
  bool has_combinable_terms() const {
    return density == "continuity" && continuity == "mass" && momentum == "symmetric_117" && viscosity == "none" &&
           (!artificial_viscosity.enabled || artificial_viscosity.form == "monaghan_1992") && !energy &&
           !(density_diffusion > 0.0 && density_diffusion_form == "hydrostatic_corrected");
  }
  ArtificialViscosityConfig artificial_viscosity;
  ArtificialConductivityConfig artificial_conductivity;
  TransportVelocityConfig transport_velocity;
  ParticleShiftingConfig particle_shifting;
  PositionCorrectionConfig position_correction;
  bool energy = false;              // energy equation (Niedoba 2012, eq 2.66/2.65), e in the state
  std::string smoothing_length = "constant";  // constant | density (Niedoba 2012, eq 2.67) | ode (Niedoba 2012, eq 2.68)
};

struct CflConfig {
  double acoustic = 0.25;  // dt <= acoustic * h / (c + |v|max)
  double force = 0.25;     // dt <= force * sqrt(h / |a|max)
  double viscous = 0.125;  // dt <= viscous * h^2 / nu
  // The top of each coefficient's range, where the explicit integrators stay stable (config/README.md,
  // "CFL coefficients"): the loader refuses larger coefficients.
  static constexpr double kMaxAcoustic = 1.0, kMaxForce = 1.0, kMaxViscous = 0.125;
  // The diffusivity of the viscous limit dt <= viscous * h^2 / diffusivity: the kinematic viscosity nu
  // (0 where the integrator treats it implicitly) and a quarter of the always explicit bulk viscosity
  // zeta, whose top eigenvalue is under a fifth of the Morris Laplacian's (physics/bulk_viscosity.hpp).
  static double diffusivity(double nu, double zeta) { return nu + 0.25 * zeta; }
};

// The Krylov solver of the implicit viscous step (leapfrog_imex, arkode_imex).
struct KrylovConfig {
  std::string solver = "pcg";  // pcg | spgmr
  double tolerance = 1e-8;     // leapfrog_imex: relative residual, in (0, 1)
  int max_iterations = 100;    // > 0
};

struct TimeConfig {
  double t_end = 0.0;                               // required, > 0
  std::string integrator = "arkode_erk";  // arkode_erk | leapfrog | leapfrog_kdk | cvode_adams | leapfrog_imex | arkode_imex
  // arkode_erk: any SUNDIALS explicit table name; arkode_imex: either table of an ARK ImEx pair
  // (config/ark_pairs.hpp), default ARKODE_ARK324L2SA_ERK_4_2_3.
  std::string table = "ARKODE_DORMAND_PRINCE_7_4_5";
  double rtol = 1e-6;                               // > 0
  double atol = 1e-12;                              // > 0 (absolute, on every state component)
  bool rtol_given = false, atol_given = false;      // set in the config or by --set (studies keep them)
  CflConfig cfl;
  std::optional<double> dt;                         // given -> fixed step (> 0)
  long max_steps = 10'000'000;                      // > 0
  KrylovConfig krylov;                              // leapfrog_imex, arkode_imex

  // Which settings the chosen integrator reads (the loader notes the others when given; the resolved
  // config writes only these).
  bool takes_table() const { return integrator == "arkode_erk" || integrator == "arkode_imex"; }
  // Error control (adaptive steps) and, for arkode_imex, its Krylov tolerance at fixed steps too.
  bool takes_tolerances() const {
    return integrator == "cvode_adams" || integrator == "arkode_imex" || (integrator == "arkode_erk" && !dt);
  }
  // A fixed step is not bounded by the CFL limits.
  bool takes_cfl() const { return !dt; }
  // The viscous term implicit: no viscous limit in the CFL step, a Krylov solver (time.krylov).
  bool implicit_viscosity() const { return integrator == "leapfrog_imex" || integrator == "arkode_imex"; }
};

struct OutputConfig {
  std::string directory = "out";
  std::vector<double> times;  // output times (> 0, increasing); t_end is always added, later
                              // times are dropped with a notice
  std::optional<double> every;  // given instead of `times`: times = every, 2 every, ... and t_end
  bool profiles = true;       // write profile CSVs at output times
  bool vtk = false;           // VTK XML PolyData particle files (.vtp) at output times + a .pvd collection
  bool vtk_walls = true;      // include wall particles in the .vtp files
  bool vtk_ghosts = false;    // include the generated ghost particles (boundary: ghost) in the .vtp files
  bool plots = false;         // PNG plots with gnuplot after the run (run/plots.hpp)
  double checkpoint_every = 0.0;  // simulated time between checkpoints [s]; 0 = none
};

// The run's health checks (run/health_check.hpp) beyond those derived from the scene.
struct HealthConfig {
  // Fluid that leaves the domain through a non-periodic face is taken out of the run (outflow,
  // run/outflow.hpp); beyond this fraction of the fluid mass the run ends as blown up.
  double max_outflow_fraction = 0.05;
};

struct Config {
  std::string source;  // file path the config came from ("<string>" for in-memory)
  std::string case_name;   // a registered case module (cases/registry.cpp)
  int dimension = 2;       // 1, 2 or 3, as the case supports
  FluidConfig fluid;
  DiscretizationConfig discretization;
  TimeConfig time;
  OutputConfig output;
  HealthConfig health;
  // The case's own sections (geometry, initial states, ...), read by its module.
  std::shared_ptr<const CaseSettings> case_settings;
  // The case's settings as its own type; a mismatch is a programming error.
  template <class T>
  const T& settings() const {
    const auto* s = dynamic_cast<const T*>(case_settings.get());
    if (!s) throw std::logic_error("config: case '" + case_name + "' has no settings of the requested type");
    return *s;
  }
  std::vector<ProbeConfig> probes;  // probes/probe_config.hpp
  // One-line remarks from loading that are not errors (e.g. output times past t_end dropped),
  // "LOCATION: key.path: text"; the caller prints them. Not part of to_yaml().
  std::vector<std::string> notices;
};

// Loads FILE, applies the "key.path=value" overrides in order (values parsed as YAML scalars or
// flow sequences), validates, and returns the resolved config. Throws ConfigError.
Config load_config(const std::string& path, const std::vector<std::string>& overrides = {});
// Same from YAML text (tests); `name` stands for the file name in messages.
Config load_config_string(const std::string& yaml, const std::vector<std::string>& overrides = {},
                          const std::string& name = "<string>");

// The resolved config as YAML (written next to the results so a run can be reproduced).
std::string to_yaml(const Config& config);

}  // namespace sphmol
