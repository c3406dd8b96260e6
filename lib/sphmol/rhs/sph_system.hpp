#pragma once
// The particle ODE system dy/dt = f(t, y) of one scene: gathers positions and velocities from y
// (and the prescribed wall motion at t), keeps the Verlet pair list current, evaluates the kernel
// once per pair, then runs the scene's terms in order. Also supplies the CFL limit.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/core/state_layout.hpp"
#include "sphmol/neighbors/verlet_list.hpp"
#include "sphmol/rhs/kernel_pass.hpp"
#include "sphmol/rhs/monitor.hpp"
#include "sphmol/rhs/particle_field_values.hpp"
#include "sphmol/rhs/particle_generator.hpp"
#include "sphmol/rhs/split_state.hpp"
#include "sphmol/rhs/state_fields.hpp"
#include "sphmol/rhs/term.hpp"
#include "sphmol/time/imex_system.hpp"
#include "sphmol/time/ode_system.hpp"

namespace sphmol {

// dt <= min(acoustic h/(c+|v|max), force sqrt(h/|a|max), viscous h^2/nu): each limit with its own
// coefficient; a limit whose denominator is zero does not apply.
struct CflLimits {
  double acoustic = 0.25, force = 0.25, viscous = 0.125;
  double sound_speed = 0.0;
  double kinematic_viscosity = 0.0;
  // discretization.bulk_viscosity's zeta [m^2/s]: explicit with every integrator (CflConfig::diffusivity).
  double bulk_viscosity = 0.0;
  // The same limits with every coefficient at the top of its stable range.
  CflLimits widest() const {
    CflLimits w = *this;
    w.acoustic = CflConfig::kMaxAcoustic;
    w.force = CflConfig::kMaxForce;
    w.viscous = CflConfig::kMaxViscous;
    return w;
  }
};

// The step the limits allow, from the per-particle extremes of an evaluation: the smallest h_i/(c_i+|v_i|)
// (`acoustic`), the largest |a_i|^2 and the smallest h_i. `viscous`: whether the viscous limit binds
// (not for the explicit part of an IMEX split). A distributed run reduces the extremes over ranks first.
inline double cfl_step(const CflLimits& cfl, double acoustic, double amax2, double hmin, bool viscous) {
  double dt = std::numeric_limits<double>::infinity();
  if (std::isfinite(acoustic)) dt = std::min(dt, cfl.acoustic * acoustic);
  if (amax2 > 0.0) dt = std::min(dt, cfl.force * std::sqrt(hmin / std::sqrt(amax2)));
  // The viscous limit: the kinematic viscosity unless it is implicit, and the (always explicit) bulk viscosity.
  const double diffusivity = CflConfig::diffusivity(viscous ? cfl.kinematic_viscosity : 0.0, cfl.bulk_viscosity);
  if (diffusivity > 0.0) dt = std::min(dt, cfl.viscous * hmin * hmin / diffusivity);
  return dt;
}

template <int D>
class SphSystem final : public OdeSystem, public ImexSystem {
 public:
  SphSystem(Particles<D> particles, Domain<D> domain, double h, std::unique_ptr<KernelPass<D>> kernel,
            std::vector<std::unique_ptr<Term<D>>> terms, std::unique_ptr<VerletList<D>> pairs, CflLimits cfl);

  // Adds the optional state blocks (before initial_state()). `energy` holds e for all particles
  // (fluid: initial value; walls: the fixed value the EOS uses); empty when the scene has no energy.
  void configure_fields(const StateFields& fields, std::vector<double> energy);
  // Per-particle h(0) for scenes whose particle spacing varies (the equal-mass shock tube): the state's
  // h(0) and the reference h of smoothing_length: density. After configure_fields, before initial_state().
  void set_initial_smoothing_lengths(const std::vector<double>& h0);

  std::size_t size() const override { return layout_.size(); }
  void rhs(double t, const double* y, double* ydot) override;
  // The explicit part of the IMEX split and the implicit part's operator (time/imex_system.hpp): the
  // same terms as rhs(), with the implicit ones recording into op instead of adding to dv/dt.
  void rhs_explicit(double t, const double* y, double* fe, ViscousOperator& op) override;
  std::vector<std::string> implicit_terms() const override;
  // The state from two sources (rhs/split_state.hpp; a rank's share in a run over ranks): the rows
  // of `split` in place of the state's, set again whenever the particle set is (not with
  // reordering). rhs_split reads the owned rows from y (layout split.owned) and the others from
  // `other`, and writes only the owned rows' rates, into ydot (that layout); the CFL extremes and
  // the step limit are then the owned rows'. rhs() and refresh_fields() still take a whole state.
  void set_split_state(SplitState<D> split);
  void rhs_split(double t, const double* y, const double* other, double* ydot);
  void rhs_explicit_split(double t, const double* y, const double* other, double* fe, ViscousOperator& op);
  // The per-particle extremes of the latest evaluation that the CFL limit is made of (cfl_step).
  struct CflExtremes {
    double acoustic = 0.0, amax2 = 0.0, hmin = 0.0;
  };
  const CflExtremes& cfl_extremes() const { return extremes_; }
  double stable_step() const override { return stable_step_; }
  double widest_stable_step() const override { return widest_step_; }
  std::size_t velocities_begin() const override { return layout_.velocities_begin(); }
  std::size_t velocities_end() const override { return layout_.velocities_end(); }
  std::size_t block_length() const override { return layout_.n; }
  long rhs_evaluations() const override { return rhs_evals_; }
  // The per-particle fields (density, pressure, ...) of the state (t, y), for measurements and output.
  // The integrator's view stays as its own last evaluation left it: the evaluation count and the CFL
  // limit are restored, so output times change neither the step sizes nor the cost reported.
  void refresh_fields(double t, const double* y, std::vector<double>& scratch) {
    const long evals = rhs_evals_;
    const double step = stable_step_, widest = widest_step_, seconds = rhs_seconds_, search = search_seconds_;
    scratch.resize(size());
    rhs(t, y, scratch.data());
    rhs_evals_ = evals;
    stable_step_ = step;
    widest_step_ = widest;
    rhs_seconds_ = seconds;
    search_seconds_ = search;
  }
  // The per-particle fields of a state evaluated elsewhere (the ranks' own particles in a run over
  // ranks), set without an evaluation: what density(), pressure(), sound_speed(), energy() and
  // smoothing_lengths() return afterwards for the scene's own particles. Every array holds one value
  // per particle of the scene in state order. With a variable h the pair list's radius follows the
  // largest h, as an evaluation sets it, so that the summary reports the serial radius.
  void set_fields(const ParticleFieldValues& f);
  // Evaluations of every kind since construction: the integrator's and refresh_fields' (which
  // rhs_evaluations() leaves out). A run over ranks checks with it that the whole scene is not evaluated.
  long evaluations_including_refreshes() const { return rhs_calls_; }
  // Wall time spent inside rhs() since construction, and the part of it that went to the neighbour
  // list (staleness test, rebuilds, reordering): the run summary splits its cost with these.
  double rhs_seconds() const { return rhs_seconds_; }
  double search_seconds() const { return search_seconds_; }
  // Per OpenMP thread: seconds on rows of fused pair passes since construction (Workspace).
  const std::vector<double>& pair_thread_seconds() const { return ws_.pair_thread_seconds; }

  // Outflow (run/outflow.hpp): fluid particles (state indices) that left the domain, taken out of the
  // simulation between steps. Each becomes Kind::Out: no neighbour search lists a pair with it (so
  // no pair sum, ghost image or wall extrapolation sees it) and every rate of it is zero from the
  // next evaluation on, so that it stays where it is. Its state (the caller sets its velocity to
  // zero) and mass stay. Indices already out are skipped. The integrator must be started again at
  // (t, y) afterwards (Integrator::restart): f(t, y) changes here. With a split state (a rank's
  // local system, rhs_split) the indices are the local fluid rows, owned or halo copies alike: a
  // halo row taken out forms no pair either, and an owned row's zero rates are the ones written. A
  // system built from particles some of which are Kind::Out already starts with them retired.
  void retire(const std::vector<std::size_t>& fluid);
  // The fluid particles taken out so far, in the order retire() was given them.
  const std::vector<std::size_t>& retired() const { return retired_; }
  bool is_retired(std::size_t i) const { return particles().kind[i] == Kind::Out; }
  // Ghost particles (or any generated set) rebuilt at every evaluation; see rhs/particle_generator.hpp.
  void set_generator(std::unique_ptr<ParticleGenerator<D>> g);
  // Locality reordering (neighbors/particle_reorder.hpp): at every Verlet-list rebuild the workspace
  // index is re-sorted along a Morton curve, particles in one cell by state index (so the order is a
  // function of the positions at the rebuild). Only the workspace is reordered: y and ydot keep the
  // state order (gathered and scattered through the permutation), so an integrator never sees it and
  // results change only by floating-point summation order. Set before the first rhs(); not with a
  // particle generator (its images refer to workspace indices of the previous order).
  void set_reorder(bool on);
  bool reorder() const { return reorder_; }
  // Workspace index -> state index of the current order (empty when reordering is off).
  const std::vector<std::uint32_t>& workspace_order() const { return perm_; }
  // Appends a term after the scene's terms.
  void append_term(std::unique_ptr<Term<D>> t);
  // A case's monitor (rhs/monitor.hpp): its term watching every fluid particle is appended after the
  // scene's terms, and the monitor is kept for the local systems of a run over ranks.
  void add_monitor(std::shared_ptr<Monitor<D>> m) {
    append_term(m->watch(WatchedRows{}));
    monitors_.push_back(std::move(m));
  }
  const std::vector<std::shared_ptr<Monitor<D>>>& monitors() const { return monitors_; }
  // Runs the pair terms in fused passes (rhs/fused_pair_pass.hpp, grouped by rhs/pair_pass_plan.hpp)
  // instead of over a stored active-pair list; results are bit-identical, memory and time lower.
  // Requires terms_needing_stored_pairs() to be empty. Set before the first rhs().
  std::vector<std::string> terms_needing_stored_pairs() const;
  // How many fused passes the terms would make (each evaluates the kernel once per pair).
  std::size_t fused_pass_count() const;
  void fuse_pair_passes();
  // The term names of each fused pass, in order; empty with the stored list.
  std::vector<std::vector<std::string>> pair_passes() const;
  // Per fused pass: true when its rows keep the skin pairs instead of being compacted to the active
  // pairs (every term of the pass adds nothing for W = F = 0, PairTerm::zero_beyond_support).
  std::vector<bool> pair_passes_keep_skin_pairs() const;
  // Symmetric fused passes (rhs/fused_pair_pass.hpp): each fluid pair evaluated once where the terms
  // allow it (the default in 1D and 2D). Off evaluates every row in full, with the same results.
  void set_symmetric_pairs(bool on);
  // Evaluations in which some fused pass ran symmetrically.
  long symmetric_evaluations() const;
  std::size_t generated_particles() const { return generator_ ? generator_->count() : 0; }
  bool has_generator() const { return generator_ != nullptr; }
  const ParticleGenerator<D>* generator() const { return generator_.get(); }
  ParticleGenerator<D>* generator() { return generator_.get(); }
  // The scene's own particles (fluid + wall); generated ones follow them in the arrays below.
  std::size_t base_particles() const { return n_base_; }
  // Positions and velocities of all particles, generated ones included, at the most recent evaluation.
  // (Before the first evaluation: zero positions, the particles' own velocities.)
  const std::array<std::vector<double>, D>& positions() const {
    if (!workspace_allocated_)
      for (int d = 0; d < D; ++d) x_out_[d].assign(n_base_, 0.0);
    return workspace_allocated_ ? ws_.x : x_out_;
  }
  const std::array<std::vector<double>, D>& velocities() const { return workspace_allocated_ ? ws_.v : particles_.v; }

  // The largest speed of any wall (wall particles over all time, and generated walls): moving walls
  // are the scene's energy input besides the body force (run/health_limits.hpp).
  double max_wall_speed() const {
    return std::max(particles_.max_wall_speed(), generator_ ? generator_->max_wall_speed() : 0.0);
  }
  const StateLayout<D>& layout() const { return layout_; }
  const Particles<D>& particles() const {
    if (released_) throw std::logic_error("SphSystem::particles: the particles were released (release_particles)");
    return particles_;
  }
  // A run over MPI ranks: the ranks other than 0 drop the whole scene's per-particle data once the
  // run's set-up has read it (their own particles live in their local systems, parallel/
  // distributed_system.hpp), so that no rank but the one writing the files holds the whole scene.
  // What stays: the layout, the domain, the counts (layout().n fluid, base_particles() in all), the
  // terms' names and passes, the pair list's radius, the monitors (without their per-particle data
  // of the whole scene, Monitor::release_whole) and the generator. particles(),
  // is_retired() and any evaluation are errors afterwards; retire() only records the indices.
  void release_particles();
  bool particles_released() const { return released_; }
  // A share of a scene (scene/scene_builder.hpp's SceneShare: a run over ranks whose ranks build
  // their own part of the scene): the system's particles are the whole scene's of global index
  // [first, first + base_particles()), fluid first as in the whole scene, of `size` particles, `fluid`
  // of them fluid. Its own state, evaluation and indices are the share's; release_particles() then
  // leaves the whole scene's counts and layout, as a released whole system has them.
  struct WholeScene {
    std::size_t first = 0, size = 0, fluid = 0;
  };
  void set_whole_scene(const WholeScene& whole);
  bool is_share() const { return share_; }
  // The scene this system is a share of (for a system that is not a share: itself).
  WholeScene whole_scene() const;
  // The whole scene's state layout (layout() with its counts).
  StateLayout<D> whole_layout() const;
  // This share's part of a whole state in the whole scene's layout (a checkpoint's), in layout().
  std::vector<double> share_of(const std::vector<double>& whole) const;
  const Domain<D>& domain() const { return domain_; }
  const CflLimits& cfl_limits() const { return cfl_; }
  double smoothing_length() const { return ws_.h; }
  // The lattice spacing the scene was assembled with (rhs/assemble.hpp; 0 when not set): h and the
  // terms' length scales (particle shifting's W(dx)) derive from it, so a system assembled again
  // from the same config and spacing (a rank's share in a run over ranks) has the same terms to the bit.
  void set_spacing(double dx) { spacing_ = dx; }
  double spacing() const { return spacing_; }
  std::vector<double> initial_state() const;
  std::vector<std::string> active_terms() const;
  std::string_view kernel_name() const { return kernel_->kernel_name(); }
  const VerletList<D>& pair_list() const { return *pairs_; }
  // The caller replaces this system before any particle has moved half the skin since its list was
  // built, and tests that itself (VerletList::keep_until_replaced): the list skips its own test.
  void keep_pair_list_until_replaced() { pairs_->keep_until_replaced(); }
  // Pairs inside the kernel support at the most recent evaluation (directed: each pair twice).
  std::size_t active_pairs() const;
  // The density and pressure of the most recent evaluation (all particles, in state order); before
  // any evaluation (or set_fields) the particles' own densities, zero pressure and sound speed.
  const std::vector<double>& density() const { return ws_.rho.empty() ? particles_.rho : state_order(ws_.rho, rho_out_); }
  const std::vector<double>& pressure() const { return ws_.p.empty() ? zeros(p_out_) : state_order(ws_.p, p_out_); }
  const std::vector<double>& sound_speed() const { return ws_.c.empty() ? zeros(c_out_) : state_order(ws_.c, c_out_); }
  const std::vector<double>& energy() const { return state_order(ws_.e, e_out_); }
  const std::vector<double>& smoothing_lengths() const { return state_order(ws_.hs, hs_out_); }
  // The density of the most recent evaluation in workspace order (fluid first, then walls and
  // generated particles): for tests that do not depend on the order, without density()'s permutation.
  const std::vector<double>& workspace_density() const { return ws_.rho.empty() ? particles_.rho : ws_.rho; }
  // The particles' kinds in that workspace order (Kind::Out: taken out, retire()).
  const std::vector<Kind>& workspace_kind() const { return ws_.particles->kind; }

 private:
  void reorder_workspace();
  // The evaluation's per-particle arrays (positions, velocities, density, pressure, sound speed,
  // strain rate), made by the first evaluation: a system that is never evaluated (the whole scene
  // each rank of a run over ranks holds) does not carry them. allocate_fields(): density, pressure
  // and sound speed only (set_fields).
  void allocate_workspace();
  void allocate_fields();
  const std::vector<double>& zeros(std::vector<double>& out) const {
    out.assign(n_base_, 0.0);
    return out;
  }
  const std::vector<double>& state_order(const std::vector<double>& w, std::vector<double>& out) const;

  Particles<D> particles_;
  bool released_ = false;  // release_particles()
  bool share_ = false;     // set_whole_scene()
  WholeScene whole_;
  Domain<D> domain_;
  StateLayout<D> layout_;
  std::unique_ptr<KernelPass<D>> kernel_;
  std::vector<std::unique_ptr<Term<D>>> terms_;
  std::vector<std::shared_ptr<Monitor<D>>> monitors_;  // add_monitor()
  std::unique_ptr<VerletList<D>> pairs_;
  CflLimits cfl_;
  std::unique_ptr<ParticleGenerator<D>> generator_;
  std::size_t n_base_ = 0;  // the scene's own particles; generated ones follow
  Workspace<D> ws_;
  StateFields fields_;
  std::vector<double> h_ref_, rho_ref_;  // h(0), rho(0) per particle for SmoothingLengthMode::density
  double support_ = 0.0;                 // kernel support in units of h
  double spacing_ = 0.0;                 // set_spacing()
  double stable_step_ = 0.0, widest_step_ = 0.0;
  long rhs_evals_ = 0, rhs_calls_ = 0;
  double rhs_seconds_ = 0.0, search_seconds_ = 0.0;
  ViscousOperator* record_ = nullptr;  // set during rhs_explicit
  SplitState<D> split_;                // set_split_state()
  bool splitting_ = false;               // during rhs_split
  const double* split_other_ = nullptr;  // the other rows of that evaluation
  CflExtremes extremes_;
  std::vector<std::size_t> retired_;  // retire(): state indices of the fluid taken out
  // Reordering: perm_[k] is the particle (state index) at workspace index k, fluid within [0, n_fluid)
  // and walls within [n_fluid, n_base); empty when off. wp_ is particles_ in workspace order, out_ the
  // derivatives in workspace order before the scatter into ydot.
  bool reorder_ = false;
  bool stored_pairs_ = true;  // the kernel pass fills ws_.pairs each evaluation (false: fused passes)
  std::vector<std::uint32_t> perm_, inv_;  // inv_: state index -> workspace index
  Particles<D> wp_;
  std::vector<double> out_;
  // Walls that follow a motion table entry (Particles::motion >= 0): set at every evaluation.
  bool moving_walls_ = false;
  typename Particles<D>::Frames frames_;           // each motion's frame at the evaluation's time
  std::array<std::vector<double>, D> normal_now_;  // wall normals at that time (workspace order); empty unless walls turn
  mutable std::vector<double> rho_out_, p_out_, c_out_, e_out_, hs_out_;
  bool workspace_allocated_ = false;               // allocate_workspace()
  mutable std::array<std::vector<double>, D> x_out_;  // positions() before the first evaluation
};

extern template class SphSystem<1>;
extern template class SphSystem<2>;
extern template class SphSystem<3>;

}  // namespace sphmol
