#include "sphmol/rhs/assemble.hpp"

#include <algorithm>

#include <functional>
#include <stdexcept>
#include <string_view>
#include <type_traits>

#include "sphmol/boundary/adami_wall_velocity.hpp"
#include "sphmol/boundary/dynamic_wall_density.hpp"
#include "sphmol/boundary/ghost_hydrostatic_pressure.hpp"
#include "sphmol/boundary/free_slip_walls.hpp"
#include "sphmol/boundary/ghost_integral_approach_matrix.hpp"
#include "sphmol/boundary/morris_wall_velocity.hpp"
#include "sphmol/boundary/repulsive_force.hpp"
#include "sphmol/boundary/wall_pressure_extrapolated.hpp"
#include "sphmol/core/join.hpp"
#include "sphmol/physics/bulk_viscosity.hpp"
#include "sphmol/physics/background_pressure.hpp"
#include "sphmol/physics/eos_tait.hpp"
#include "sphmol/physics/artificial_conductivity.hpp"
#include "sphmol/physics/artificial_conductivity_ia.hpp"
#include "sphmol/physics/artificial_viscosity.hpp"
#include "sphmol/physics/artificial_viscosity_ia.hpp"
#include "sphmol/physics/body_force.hpp"
#include "sphmol/physics/continuity_density.hpp"
#include "sphmol/physics/continuity_density_ia.hpp"
#include "sphmol/physics/density_diffusion.hpp"
#include "sphmol/physics/energy_equation.hpp"
#include "sphmol/physics/energy_equation_ia.hpp"
#include "sphmol/physics/integral_approach_matrix.hpp"
#include "sphmol/physics/eos_ideal_gas.hpp"
#include "sphmol/physics/normalised_summation_density.hpp"
#include "sphmol/physics/pressure_gradient_116.hpp"
#include "sphmol/physics/smoothing_length_rate.hpp"
#include "sphmol/physics/eos_linear.hpp"
#include "sphmol/physics/morris_moment.hpp"
#include "sphmol/physics/morris_viscosity.hpp"
#include "sphmol/physics/pressure_gradient.hpp"
#include "sphmol/physics/pressure_gradient_ia.hpp"
#include "sphmol/physics/strain_rate.hpp"
#include "sphmol/physics/strain_rate_viscosity.hpp"
#include "sphmol/physics/summation_density.hpp"
#include "sphmol/kernels/registry.hpp"
#include "sphmol/physics/particle_shifting.hpp"
#include "sphmol/physics/transport_velocity.hpp"
#include "sphmol/physics/weakly_compressible_row.hpp"
#include "sphmol/physics/xsph.hpp"
#include "sphmol/rhs/kernel_pass_variable_h.hpp"

namespace sphmol {

template <int D>
std::unique_ptr<SphSystem<D>> assemble_system(const Config& config, Particles<D> particles, const Domain<D>& domain,
                                              double spacing, const BoxWalls<D>* walls, std::vector<double> energy,
                                              const std::vector<GhostPlane<D>>& planes) {
  const auto& disc = config.discretization;
  const auto& fluid = config.fluid;
  const double h = disc.smoothing_ratio * spacing;
  const bool variable_h = disc.smoothing_length != "constant";
  // A kernel its source does not define in D is rejected by the registry; the key says which setting.
  std::unique_ptr<KernelPass<D>> kernel;
  try {
    kernel = variable_h ? make_variable_h_kernel_pass<D>(disc.kernel) : make_kernel_pass<D>(disc.kernel);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("discretization.kernel: ") + e.what());
  }
  const double mu = fluid.density * fluid.kinematic_viscosity;

  // Term order: the density (when summed, every later term reads it), then the per-particle state
  // (ghost copies, EOS, wall pressures), then every pair sum, then what reads their totals. Pair sums
  // with no dependence on each other sit together, so that fused passes group them (rhs/pair_pass_plan.hpp).
  std::vector<std::unique_ptr<Term<D>>> terms;
  // Every term goes in through here: checked against D with the key that chose it (rhs/term.hpp).
  const auto add = [&terms](std::string_view key, std::unique_ptr<Term<D>> term) {
    require_dimension(*term, key);
    terms.push_back(std::move(term));
  };
  if (disc.density == "summation") add("discretization.density", std::make_unique<SummationDensity<D>>());
  else if (disc.density == "normalised_summation") add("discretization.density", std::make_unique<NormalisedSummationDensity<D>>());
  else if (disc.density != "continuity") throw std::invalid_argument("discretization.density: unsupported '" + disc.density + "'");
  // Wall treatments: the global wall_pressure, or per wall body (a scene's walls[i].treatment).
  const WallTreatment global_walls = disc.wall_pressure == "extrapolated" ? WallTreatment::extrapolated
                                     : disc.wall_pressure == "dynamic"    ? WallTreatment::dynamic
                                                                          : WallTreatment::rest;
  const auto walls_with = [&](WallTreatment t) { return global_walls == t || particles.any_body_treatment(t); };
  const bool dynamic_walls = walls_with(WallTreatment::dynamic);
  std::unique_ptr<GhostGenerator<D>> ghosts;
  if (!planes.empty() && disc.boundary != "ghost") throw std::invalid_argument("ghost mirror planes need discretization.boundary: ghost");
  if (disc.boundary == "ghost") {
    if (!walls) throw std::invalid_argument("discretization.boundary: ghost needs a scene with planar walls");
    // Images of every particle within the kernel support of a wall; the set is rebuilt each evaluation.
    ghosts = std::make_unique<GhostGenerator<D>>(*walls, kernel->support(), planes);
    add("discretization.boundary", std::make_unique<GhostStateCopy<D>>(ghosts.get()));
  }
  std::array<double, D> g{};
  bool any_force = false;
  for (int d = 0; d < D && d < static_cast<int>(fluid.body_force.size()); ++d) {
    g[d] = fluid.body_force[d];
    any_force = any_force || g[d] != 0.0;
  }
  std::function<double(double)> rho_of_p;  // the EOS inverted, for extrapolated wall pressures
  if (fluid.eos.type == "ideal_gas") {
    if (!disc.energy) throw std::invalid_argument("fluid.eos.type: 'ideal_gas' needs discretization.energy: true");
    add("fluid.eos.type", std::make_unique<IdealGasEos<D>>(fluid.eos.gamma));
  } else if (fluid.eos.type == "tait") {
    const TaitLaw law(fluid.eos.sound_speed, fluid.density, fluid.eos.gamma);
    add("fluid.eos.type", std::make_unique<TaitEos<D>>(fluid.eos.sound_speed, fluid.density, fluid.eos.gamma,
                                                 fluid.eos.clamp_negative));
    rho_of_p = [law](double p) { return law.density(p); };
  } else if (fluid.eos.type == "linear" || fluid.eos.type == "linear_relative") {
    const bool rel = fluid.eos.type == "linear_relative";
    const double c2 = fluid.eos.sound_speed * fluid.eos.sound_speed, rho0 = fluid.density;
    add("fluid.eos.type", std::make_unique<LinearEos<D>>(fluid.eos.sound_speed, fluid.density, rel));
    rho_of_p = [c2, rho0, rel](double p) { return p / c2 + (rel ? rho0 : 0.0); };
  } else {
    throw std::invalid_argument("fluid.eos.type: unsupported '" + fluid.eos.type + "'");
  }
  if (ghosts && any_force) {
    if (!rho_of_p) throw std::invalid_argument("discretization.boundary: ghost walls under a body force need a barotropic EOS");
    add("discretization.boundary", std::make_unique<GhostHydrostaticPressure<D>>(ghosts.get(), g, fluid.body_force_ramp, rho_of_p));
  }
  if (fluid.eos.background_pressure > 0.0) add("fluid.eos.background_pressure", std::make_unique<BackgroundPressure<D>>(fluid.eos.background_pressure));
  if (walls_with(WallTreatment::extrapolated)) {
    if (!rho_of_p) throw std::invalid_argument("discretization.wall_pressure: extrapolated needs a barotropic EOS");
    add("discretization.wall_pressure", std::make_unique<WallPressureExtrapolated<D>>(
        g, fluid.body_force_ramp, rho_of_p, particles.treatment_mask(WallTreatment::extrapolated, global_walls)));
  }
  const bool m116 = disc.momentum == "symmetric_116";
  // The integral approach (physics/integral_approach_matrix.hpp): every gradient of the gas dynamics
  // (continuity, pressure, artificial viscosity and conductivity, energy) through the matrices C_i.
  const bool ia = disc.momentum == "integral_approach";
  if (!m116 && !ia && disc.momentum != "symmetric_117")
    throw std::invalid_argument("discretization.momentum: unsupported '" + disc.momentum + "'");
  if (ia) {
    // Terms with no IA form would mix the two gradients.
    // Config errors (exit 2): the loader's checks (config/scene_checks.cpp) say so first with the line.
    if (disc.viscosity != "none")
      throw ConfigError("discretization.momentum: integral_approach needs viscosity: none (got '" + disc.viscosity + "')");
    if (disc.density_diffusion > 0.0)
      throw ConfigError("discretization.momentum: integral_approach is not available with density_diffusion");
  }
  const auto& av = disc.artificial_viscosity;
  // Continuity, delta-SPH, pressure and artificial viscosity (each of the last three optional) in one
  // pair loop (the dam break's formulation), equal to the separate terms to round-off.
  const bool signal_velocity = av.form == "monaghan_1997";
  const bool hydrostatic_diffusion = disc.density_diffusion > 0.0 && disc.density_diffusion_form == "hydrostatic_corrected";
  const bool wc_row = disc.combine_terms && disc.has_combinable_terms();
  const MonaghanPi monaghan{av.alpha, av.beta, av.eta, av.band_width(), av.band_offset()};
  const double diffusion = disc.density_diffusion * h * fluid.eos.sound_speed;
  if (wc_row) {
    // Without artificial viscosity the row runs with Pi_ij = 0: alpha = beta = 0, and an eta that keeps
    // its denominator positive for coincident particles.
    const MonaghanPi pi = av.enabled ? monaghan : MonaghanPi{0.0, 0.0, 0.1};
    if (diffusion > 0.0) add("discretization.combine_terms", std::make_unique<WeaklyCompressibleRow<D, true>>(diffusion, pi, av.enabled));
    else add("discretization.combine_terms", std::make_unique<WeaklyCompressibleRow<D, false>>(0.0, pi, av.enabled));
  }
  // The IA matrices: after the densities of every particle (ghost copies included) and before any
  // term that reads them.
  std::shared_ptr<IntegralApproachField<D>> ia_field;
  if (ia) {
    ia_field = std::make_shared<IntegralApproachField<D>>();
    if (variable_h) ia_field->kernel = kernel_info<D>(disc.kernel).W;
    const GhostGenerator<D>* gen = ghosts.get();
    add("discretization.momentum", std::make_unique<IntegralApproachMatrix<D>>(
        ia_field, gen ? std::function<std::size_t()>([gen] { return gen->base(); }) : nullptr));
    if (ghosts) add("discretization.momentum", std::make_unique<GhostIntegralApproachMatrix<D>>(ghosts.get(), ia_field));
  }
  if (disc.density == "continuity" && ia) {
    if (disc.continuity == "volume") add("discretization.continuity", std::make_unique<ContinuityDensityIA<D, true>>(ia_field));
    else add("discretization.density", std::make_unique<ContinuityDensityIA<D, false>>(ia_field));
  } else if (disc.density == "continuity" && !wc_row) {
    if (disc.continuity == "volume") add("discretization.continuity", std::make_unique<ContinuityDensity<D, true>>());
    else add("discretization.density", std::make_unique<ContinuityDensity<D>>());
  }
  if (dynamic_walls)
    add("discretization.wall_pressure",
        std::make_unique<DynamicWallDensity<D>>(particles.treatment_mask(WallTreatment::dynamic, global_walls)));
  if (hydrostatic_diffusion)
    add("discretization.density_diffusion_form", std::make_unique<HydrostaticDensityDiffusion<D>>(
                                                     disc.density_diffusion, h, fluid.eos.sound_speed, g, fluid.body_force_ramp));
  else if (disc.density_diffusion > 0.0 && !wc_row)
    add("discretization.density_diffusion", std::make_unique<DensityDiffusion<D>>(disc.density_diffusion, h, fluid.eos.sound_speed));
  auto pressure = [m116, ia, &ia_field]() -> std::unique_ptr<Term<D>> {
    if (ia) return std::make_unique<PressureGradientIA<D>>(ia_field);
    if (m116) return std::make_unique<PressureGradient116<D>>();
    return std::make_unique<PressureGradient117<D>>();
  };
  // The Morris extrapolation reads each wall particle's normal and depth; ghost images and repulsive
  // rows have none (the loader refuses the combination, and so must the assembly: a ghost image's
  // index lies past the particles' wall arrays).
  if (disc.wall_model != "prescribed" && disc.boundary != "wall_particles")
    throw std::invalid_argument("discretization.wall_model: " + disc.wall_model + " needs boundary: wall_particles (got '" + disc.boundary +
                                "'); use wall_model: prescribed");
  // Fluids of several viscosities (Particles::viscosity): Morris' form with each particle's own mu.
  const bool variable_mu = !particles.viscosity.empty();
  // A viscous term of a fluid without viscosity adds zeros (viscosity: morris is the default): with the
  // explicit integrators it is not built, nor are the wall velocities only it reads. The implicit ones
  // keep it, as the implicit side of their split.
  const bool viscous = disc.viscosity != "none" && (variable_mu || mu > 0.0 || config.time.implicit_viscosity());
  if (ghosts && !viscous) ghosts->without_viscous_terms();
  if (disc.wall_model == "adami") {
    // Adami et al. (2012): no-slip velocities for the viscous term, and the extrapolated pressure.
    if (disc.wall_pressure != "extrapolated")
      throw std::invalid_argument("discretization.wall_model: adami needs wall_pressure: extrapolated (got '" + disc.wall_pressure + "')");
    if (disc.viscosity == "strain_rate")
      throw std::invalid_argument("discretization.wall_model: adami needs viscosity: morris or none");
    if (viscous) add("discretization.wall_model", std::make_unique<AdamiWallVelocity<D>>());
  } else if (disc.wall_model == "morris") {
    if (viscous) add("discretization.wall_model", std::make_unique<MorrisWallVelocity<D>>(disc.wall_beta_max, disc.viscosity == "strain_rate"));
  } else if (disc.wall_model != "prescribed")
    throw std::invalid_argument("discretization.wall_model: unsupported '" + disc.wall_model + "'");
  // Free-slip wall bodies: after the wall model, which sets every wall pair's factor.
  if (viscous &&
      std::any_of(particles.free_slip_body.begin(), particles.free_slip_body.end(), [](std::uint8_t f) { return f != 0; }))
    add("discretization.viscosity", std::make_unique<FreeSlipWalls<D>>(particles.free_slip_body, disc.viscosity == "strain_rate"));
  if (variable_mu && disc.viscosity != "morris")
    throw std::invalid_argument("fluid bodies of their own kinematic_viscosity need discretization.viscosity: morris");
  if (!viscous) {
    if (!wc_row) add("discretization.momentum", pressure());
  } else if (disc.viscosity == "strain_rate") {
    add("discretization.viscosity", std::make_unique<StrainRate<D>>());
    add("discretization.momentum", pressure());
    add("discretization.viscosity", std::make_unique<StrainRateViscosity117<D>>(mu));
  } else if (disc.viscosity == "morris") {
    using LC = LaplacianCorrection;
    // One term of the correction C and of Variable (fluids of several mu) each.
    const auto morris = [&](auto c, std::shared_ptr<const MorrisMomentField> moment) {
      constexpr LC C = decltype(c)::value;
      if (variable_mu) add("discretization.viscosity", std::make_unique<MorrisViscosity<D, C, true>>(mu, moment));
      else add("discretization.viscosity", std::make_unique<MorrisViscosity<D, C>>(mu, moment));
    };
    if (disc.laplacian_correction == "moment_symmetric") {
      // The moments in a pass of their own: each viscous row reads its neighbours' M_j.
      auto moment = std::make_shared<MorrisMomentField>();
      add("discretization.laplacian_correction", std::make_unique<MorrisMoment<D>>(moment));
      add("discretization.momentum", pressure());
      morris(std::integral_constant<LC, LC::moment_symmetric>{}, moment);
    } else {
      add("discretization.momentum", pressure());
      if (disc.laplacian_correction == "moment") morris(std::integral_constant<LC, LC::moment>{}, nullptr);
      else if (disc.laplacian_correction == "none") morris(std::integral_constant<LC, LC::none>{}, nullptr);
      else throw std::invalid_argument("discretization.laplacian_correction: unsupported '" + disc.laplacian_correction + "'");
    }
  } else {
    throw std::invalid_argument("discretization.viscosity: unsupported '" + disc.viscosity + "'");
  }
  // Bulk viscosity: the divergences in a pass of their own, then the viscous pressure that reads them.
  // (Not with ghost walls: the loader refuses them, physics/velocity_divergence.hpp says why.)
  const double zeta = disc.bulk_zeta(fluid.eos.sound_speed, h);
  if (zeta > 0.0) {
    auto div = std::make_shared<VelocityDivergenceField>();
    add("discretization.bulk_viscosity", std::make_unique<VelocityDivergence<D>>(div));
    add("discretization.bulk_viscosity", std::make_unique<BulkViscosity<D>>(zeta, div));
  }
  if (av.enabled && !wc_row) {
    const SignalVelocityPi sv{av.alpha, av.beta, av.band_width(), av.band_offset()};
    // The term for a Pi form and the energy flag, with the integral approach's gradients or the kernel's.
    const auto add_viscosity = [&]<bool WithEnergy>(const auto& pi) {
      using Pi = std::decay_t<decltype(pi)>;
      if (ia) add("discretization.artificial_viscosity", std::make_unique<ArtificialViscosityIA<D, WithEnergy, Pi>>(pi, ia_field));
      else add("discretization.artificial_viscosity", std::make_unique<ArtificialViscosity<D, WithEnergy, Pi>>(pi));
    };
    if (signal_velocity && disc.energy) add_viscosity.template operator()<true>(sv);
    else if (signal_velocity) add_viscosity.template operator()<false>(sv);
    else if (disc.energy) add_viscosity.template operator()<true>(monaghan);
    else add_viscosity.template operator()<false>(monaghan);
  }
  if (disc.artificial_conductivity.enabled && ia)
    add("discretization.artificial_conductivity", std::make_unique<ArtificialConductivityIA<D>>(disc.artificial_conductivity.alpha, ia_field));
  else if (disc.artificial_conductivity.enabled)
    add("discretization.artificial_conductivity", std::make_unique<ArtificialConductivity<D>>(disc.artificial_conductivity.alpha));
  if (disc.energy) {
    if (ia) add("discretization.energy", std::make_unique<EnergyEquationIA<D>>(ia_field));
    else if (m116) add("discretization.energy", std::make_unique<EnergyEquation<D, EnergyForm::symmetric_116>>());
    else add("discretization.energy", std::make_unique<EnergyEquation<D, EnergyForm::symmetric_117>>());
  }
  if (disc.boundary == "virtual_repulsive") {
    const RepulsiveLaw law{disc.repulsive.strength, disc.repulsive.p1, disc.repulsive.p2, disc.repulsive.r0 * spacing};
    if (law.r0 >= kernel->support() * h)
      throw std::invalid_argument("discretization.repulsive.r0: must lie inside the kernel support (" +
                                  std::to_string(kernel->support() * h / spacing) + " spacings)");
    add("discretization.boundary", std::make_unique<RepulsiveBoundary<D>>(law));
  }
  if (particles.any_body_treatment(WallTreatment::repulsive))
    add("discretization.boundary", std::make_unique<RepulsiveBoundary<D>>(particles.body_repulsion, particles.body_count()));
  if (disc.xsph > 0.0) add("discretization.xsph", std::make_unique<Xsph<D>>(disc.xsph));
  if (const auto& tv = disc.transport_velocity; tv.enabled) {
    const double c = fluid.eos.sound_speed;
    auto du = tv.extra_stress ? std::make_shared<TransportShiftField<D>>() : nullptr;
    add("discretization.transport_velocity", std::make_unique<TransportVelocityShift<D>>(
        tv.background_pressure > 0.0 ? tv.background_pressure : fluid.density * c * c, tv.step_factor * h / c, du));
    if (du) add("discretization.transport_velocity.extra_stress", std::make_unique<TransportVelocityStress<D>>(du));
  }
  if (const auto& ps = disc.particle_shifting; ps.enabled) {
    if (!(ps.velocity > 0.0)) throw std::invalid_argument("discretization.particle_shifting.velocity: must be > 0");
    add("discretization.particle_shifting", std::make_unique<ParticleShifting<D>>(
        ps.coefficient, ps.velocity, h, kernel_info<D>(disc.kernel).W(spacing, h), ps.correction));
  }
  // Reads the complete drho/dt (Niedoba 2012, eq 2.68), so after every density sum.
  if (disc.smoothing_length == "ode") add("discretization.smoothing_length", std::make_unique<SmoothingLengthRate<D>>());
  // Per particle and read by nothing else: last, so that it never splits a fused pass.
  if (any_force) add("fluid.body_force", std::make_unique<BodyForce<D>>(g, fluid.body_force_ramp));

  auto list = std::make_unique<VerletList<D>>(make_neighbor_search<D>(disc.neighbor_search), kernel->support() * h,
                                              disc.skin * h);
  // The viscous limit of the most viscous fluid: nu = mu / rho0 of each particle.
  double nu_max = fluid.kinematic_viscosity;
  if (variable_mu) {
    nu_max = 0.0;
    for (std::size_t i = 0; i < particles.n_fluid; ++i)
      nu_max = std::max(nu_max, particles.viscosity[i] / (particles.rest_density.empty() ? fluid.density : particles.rest_density[i]));
  }
  CflLimits cfl{config.time.cfl.acoustic, config.time.cfl.force, config.time.cfl.viscous,
                fluid.eos.type == "ideal_gas" ? 0.0 : fluid.eos.sound_speed, nu_max, zeta};
  auto sys = std::make_unique<SphSystem<D>>(std::move(particles), domain, h, std::move(kernel), std::move(terms),
                                            std::move(list), cfl);
  StateFields fields;
  fields.density = disc.density == "continuity";
  fields.energy = disc.energy;
  fields.wall_density = dynamic_walls;
  fields.wall_density_floor = fluid.density;
  fields.wall_density_floor_width = disc.wall_density_floor_width * fluid.density;
  if (disc.wall_density_floor_width_given && !dynamic_walls)
    throw ConfigError("discretization.wall_density_floor_width: is the floor of dynamic wall particles' density, "
                                "and no wall is dynamic (discretization.wall_pressure '" + disc.wall_pressure +
                                "' and no scene body with treatment: dynamic)");
  if (disc.smoothing_length == "density") fields.smoothing_length = SmoothingLengthMode::density;
  if (disc.smoothing_length == "ode") fields.smoothing_length = SmoothingLengthMode::ode;
  if (disc.energy && energy.empty())
    throw std::invalid_argument("discretization.energy: case '" + config.case_name + "' provides no initial energy");
  sys->configure_fields(fields, std::move(energy));
  sys->set_spacing(spacing);
  if (ghosts) sys->set_generator(std::move(ghosts));
  sys->set_reorder(disc.reorder);
  const auto unfusable = sys->terms_needing_stored_pairs();
  if (disc.pair_passes == "fused" && !unfusable.empty())
    throw std::invalid_argument("discretization.pair_passes: 'fused' is not available with " + join(unfusable) +
                                " (they need the stored pair list); use 'auto' or 'stored'");
  // auto: fused when one pass holds every pair term (one kernel evaluation per pair either way, and no
  // stored list: 1.2-1.5x faster on the dam break, equal on the shock tube). A scene that needs several
  // passes evaluates the kernel once per pass, and there the stored list is faster (Taylor-Green
  // without its Laplacian correction, three passes: 1.4-1.7x; Poiseuille, two: 1.5x) at about three
  // times the memory (README, Performance); `fused` is then the choice for memory.
  const bool fuse_auto = unfusable.empty() && sys->fused_pass_count() <= 1;
  if (disc.pair_passes == "fused" || (disc.pair_passes == "auto" && fuse_auto)) sys->fuse_pair_passes();
  return sys;
}

template std::unique_ptr<SphSystem<1>> assemble_system<1>(const Config&, Particles<1>, const Domain<1>&, double, const BoxWalls<1>*, std::vector<double>, const std::vector<GhostPlane<1>>&);
template std::unique_ptr<SphSystem<2>> assemble_system<2>(const Config&, Particles<2>, const Domain<2>&, double, const BoxWalls<2>*, std::vector<double>, const std::vector<GhostPlane<2>>&);
template std::unique_ptr<SphSystem<3>> assemble_system<3>(const Config&, Particles<3>, const Domain<3>&, double, const BoxWalls<3>*, std::vector<double>, const std::vector<GhostPlane<3>>&);

}  // namespace sphmol
