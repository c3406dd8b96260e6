#pragma once
// The particle ODE system of one rank in a run over several ranks: the rank owns part of the
// particles (recursive coordinate bisection by pair count, rcb_partition.hpp) and its state holds
// theirs only; an evaluation hands the owned particles together with halo copies of other ranks'
// particles to an ordinary SphSystem, assembled from the same config (rhs/assemble.hpp), whose
// terms run unchanged. The integrator sees an OdeSystem like any other.
//
// Deep halo instead of exchanges between passes: a pass reads, at neighbours, what the pass before
// computed (summation density's rho_j, then the EOS's p_j). The halo here reaches P times the
// list radius (kernel support + skin) for a scene of P dependent pair passes, so every particle a
// pass reads at an owned particle's neighbour has all its own neighbours on the rank: its values
// are computed here as on its owner, and the state alone is exchanged, once per evaluation. The
// price is redundant work on the halo rows (one pass: none beyond the halo itself).
//
// Bit for bit the serial result: global ids number the particles as the serial scene does (fluid
// first), and the local set is in global-id order, so every neighbour row (sorted by index, as
// every search makes it) lists the serial neighbours in the serial order, and every per-particle
// sum is the serial sum. The CFL limit is reduced over ranks with min/max, which are exact.
//
// Ghost (mirror) walls: each local system mirrors its own fluid particles, owned and halo, at every
// evaluation (boundary/ghost_particles.hpp). An image is never nearer to a particle in front of its
// mirror than its source is, so the images an owned row reads come from halo sources, and they are
// appended in the order of their sources, as in the serial run: every row lists the serial images in
// the serial order, with the fields their sources have on their owners (the deep halo computes them
// alike). A fluid particle behind a mirror brings images nearer than their sources by up to twice
// its depth behind it, per mirror; the halo reaches that much farther (mirror_margin()).
//
// The halo plan is made again, with a new local system, when some particle has moved more than half
// the skin since the last plan (the Verlet rule, halo.hpp); the local system's own list, built at the
// plan's positions, skips its own test then (VerletList::keep_until_replaced), which could never find
// it stale first. With a variable h the list radius is the
// kernel support of the largest h over all ranks (reduced at every evaluation): the halo reaches P
// such radii at the plan, and the support's growth since then eats into the skin, as in the
// Verlet list (neighbors/verlet_list.hpp). After such a re-plan, when the largest
// rank's pair work has drifted past `rebalance_threshold` times the mean, the particles are
// partitioned again by their current pair counts and migrate with their state (repartition(),
// between steps, with whatever per-particle arrays the integrator carries).
//
// A case's monitors (rhs/monitor.hpp, declared on the whole system): every local system gets each
// monitor's term watching the fluid particles the rank owns, by their global ids, so that they see
// every evaluation as the serial system's do; the results stay in the monitors, across halo plans
// and repartitions, and MpiRun combines them over the ranks where the case reads them.
//
// Outflow (run/outflow.hpp): fluid that has left the domain is taken out of the run between steps
// (take_out()) by the global ids every rank has learnt from the health check: each rank zeroes the
// velocities of its own leavers in its state, marks them Kind::Out among its owned particles, and
// retires them and the halo copies it holds in its local system (SphSystem::retire), so that no rank
// pairs with them. The kind travels with the particles in the halo exchange of later plans and in
// migrations, and each new local system starts with the rows that arrive as Kind::Out retired (plan()).
//
// SUNDIALS integrators wrap the rank's state in an MPI vector (wrap_state: N_VMake_Parallel over
// the owned rows, no copy) whose weighted RMS norm is a fixed-point sum reduced over the ranks
// (fixed_point_norm_mpi.hpp): every rank sees the serial run's error norms and takes its steps. An
// evaluation at a stage state refreshes the halo from that state like any other, since the state
// alone is exchanged per evaluation.
//
// Reordering (discretization.reorder, neighbors/particle_reorder.hpp): the serial run sorts its
// workspace along a Morton curve at each rebuild of its neighbour list, particles in one cell by
// state index, and its rows list their neighbours in that order. Each rank runs the serial list's
// displacement test on the whole scene (serial_list_stale(): every particle's displacement since the
// serial rebuild, reduced over the ranks, with the serial support and skin) and, where the serial
// run rebuilds, keeps each particle's position there, which moves with it and travels with the halo.
// A local system (assembled without reordering) then holds its particles in the serial workspace's
// order, by the Morton codes of those positions on the serial grid and ties by global id, and is made
// again at every serial rebuild: every row lists the serial neighbours in the serial order.
//
// The implicit-explicit integrators (arkode_imex, leapfrog_imex) see an ImexSystem: rhs_explicit
// records the viscous operator of the owned fluid rows, taken from the local system's operator,
// whose columns past the owned rows are halo velocities (velocity_halo.hpp). Applying it fetches
// those from their owners by the evaluation's halo plan; its rows are the serial operator's rows
// with their entries in the serial order, and the Krylov solves' dot products are exact sums
// reduced over the ranks, so the stage solves iterate as the serial ones do, to the bit.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sphmol/boundary/ghost_particles.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/halo.hpp"
#include "sphmol/parallel/rcb_partition.hpp"
#include "sphmol/parallel/fixed_point_norm_mpi.hpp"
#include "sphmol/parallel/vector_family.hpp"
#include "sphmol/rhs/sph_system.hpp"
#include "sphmol/parallel/velocity_halo.hpp"
#include "sphmol/time/imex_system.hpp"
#include "sphmol/time/ode_system.hpp"
#include "sphmol/time/state_vector.hpp"

namespace sphmol::parallel {

template <int D>
class DistributedSystem final : public OdeSystem, public ImexSystem, public StateVectorMaker {
 public:
  // Collective. `whole`: the whole scene (every rank builds it, from `config`), before any
  // evaluation; its particle index is the global id. imbalance_tolerance (> 1): the partition's aim
  // for the largest rank's pair work over the mean; rebalance_threshold: the imbalance past which
  // imbalanced() asks for a new partition.
  // (t0, y0): the whole state the run starts from, which places the particles for the partition.
  // Neither is read once the rank has taken its slice of them: every per-particle value moves with
  // the particles from there, and `scene_read` (when set) is called on every rank at that point,
  // before the partition's searches, so that the caller can release them
  // (SphSystem::release_particles). take_initial_state(): this rank's part of y0 afterwards.
  DistributedSystem(const Communicator& comm, const Config& config, const SphSystem<D>& whole, const std::vector<double>& y0,
                    double t0, double imbalance_tolerance, double rebalance_threshold,
                    const std::function<void()>& scene_read = {});
  ~DistributedSystem() override;

  std::size_t size() const override { return layout_.size(); }
  // Collective: every rank evaluates at the same t (the integrators' step decisions rest on
  // reductions, the same on every rank).
  void rhs(double t, const double* y, double* ydot) override;
  // Collective: f_E and the viscous operator of the owned fluid rows (ImexSystem).
  void rhs_explicit(double t, const double* y, double* fe, ViscousOperator& op) override;
  std::vector<std::string> implicit_terms() const override { return implicit_terms_; }
  void minimum_everywhere(double* values, std::size_t count) const override;
  // Collective: an MPI vector over this rank's part of the state (N_VMake_Parallel, no copy), its
  // norm the fixed-point one of the serial run (fixed_point_norm_mpi.hpp). It and its clones move
  // with the particles at a repartition.
  N_Vector wrap_state(double* data, std::size_t length, SUNContext ctx) const override;
  double stable_step() const override { return stable_step_; }
  double widest_stable_step() const override { return widest_step_; }
  double first_stable_step() const { return first_stable_step_; }  // of the first evaluation
  std::size_t velocities_begin() const override { return layout_.velocities_begin(); }
  std::size_t velocities_end() const override { return layout_.velocities_end(); }
  std::size_t block_length() const override { return layout_.n; }
  long rhs_evaluations() const override { return rhs_evals_; }

  const StateLayout<D>& layout() const { return layout_; }
  const StateLayout<D>& whole_layout() const { return whole_layout_; }
  // This rank's part of a whole state (the serial layout), and (collective) the whole state from
  // every rank's part, on rank 0 only (the one that measures and writes); returns true there. On the
  // other ranks `whole` is left as it was: no rank but the root holds a gathered copy of the scene.
  std::vector<double> local_part(const std::vector<double>& whole) const;
  // The particles this rank built of the scene: all of them, or its share (SphSystem::is_share).
  std::size_t scene_particles_built() const { return scene_particles_built_; }
  // This rank's part of the constructor's y0 (once; empty afterwards).
  std::vector<double> take_initial_state() { return std::move(initial_state_); }
  bool gather(const double* y, std::vector<double>& whole) const;

  // Collective, between steps: true when the halo was planned again since the last call and the
  // load imbalance (pair work of the owned rows, over the mean) now exceeds the threshold.
  bool imbalanced();
  // Collective, after imbalanced() said true: a new partition by the current pair counts at (t, y);
  // the particles move with y and with the integrator's arrays of the state's length (`state`) or
  // of its position block's (`positions`), which are all resized to the new share. Every live
  // vector made by wrap_state, and every clone of it (a SUNDIALS integrator's history), moves too,
  // and those that wrapped y wrap its new storage (vector_family.hpp).
  void repartition(double t, std::vector<double>& y, const std::vector<std::vector<double>*>& state,
                   const std::vector<std::vector<double>*>& positions);

  // Between steps, not collective: the fluid particles of global ids `gone` (ascending, the same on
  // every rank) leave the run: the velocities of this rank's own ones are zeroed in y (this rank's
  // state) and they become Kind::Out, here and in the local system with the halo copies of the others.
  void take_out(const std::vector<std::size_t>& gone, double* y);

  // Collective, at an output time: the local system (owned + halo particles) with its fields at
  // (t, y), y this rank's state, as SphSystem::refresh_fields sets them (no evaluation counted, the
  // step limit kept; the halo is planned again if it is due). Its owned rows then hold the whole
  // system's values, so each rank can write its own particles (run/owned_piece.hpp).
  void refresh_local(double t, const double* y);
  const SphSystem<D>& local_system() const { return *local_; }
  const std::vector<double>& local_state() const { return y_local_; }
  // The local system's row of each owned particle, and the global id of each local row (fluid, then
  // walls, each ascending, or in the serial workspace's order when reordering; ghost images have none).
  const std::vector<std::uint32_t>& owned_rows() const { return owned_at_; }
  const std::vector<std::uint64_t>& local_gid() const { return local_gid_; }

  // Owned particles: fluid first; the global id of each; the density of the latest evaluation.
  const Particles<D>& owned() const { return owned_; }
  const std::vector<std::uint64_t>& gid() const { return gid_; }
  double owned_density(std::size_t o) const;
  const Domain<D>& domain() const { return domain_; }
  // Whether the monitors watch the evaluations (true unless set otherwise): not while an integrator
  // starts again on a new share (MpiRun::rebalance), whose evaluation the serial run does not make.
  void watch_evaluations(bool on) { *watching_ = on; }
  const std::vector<std::shared_ptr<Monitor<D>>>& monitors() const { return monitors_; }
  // The terms of the local systems (the scene's, from the config; empty before the first evaluation).
  std::vector<std::string> active_terms() const { return local_ ? local_->active_terms() : std::vector<std::string>{}; }

  struct Stats {
    long plans = 0;                 // halo plans (the first included)
    long rebuilds = 0;              // neighbour-list rebuilds of the local systems
    std::size_t halo = 0;           // halo particles of the current plan
    std::size_t halo_max = 0;       // the most over the run
    int depth = 1;                  // halo depth, in list radii
    double exchange_seconds = 0.0;  // state exchanges and their reductions
    double rhs_seconds = 0.0;       // in rhs(), everything included
    double search_seconds = 0.0;    // displacement tests, halo plans and the local neighbour lists
    double imbalance = 1.0;         // largest rank's pair work over the mean, at the last partition
    double imbalance_seen = 1.0;    // the same, at the last re-plan
    long repartitions = 0;          // partitions after the first
    double mirror_margin_max = 0.0; // the deepest crossing of a ghost mirror, times 2 D, over the run (m)
    long serial_sorts = 0;          // reordering: rebuilds of the serial list, each a new local order
  };
  Stats stats() const;
  // Pairs in the rows of the current local neighbour list: the owned rows' (this rank's share of
  // the pair work) and the halo rows' (computed only for the values the owned rows read there).
  std::pair<std::uint64_t, std::uint64_t> pair_work() const;

 private:
  // Positions of the owned particles at t (fluid from y, walls from their motion), wrapped, into
  // x_now_ (current after prepare_local() only when a plan was made or the scene has ghost walls).
  void owned_positions(double t, const double* y);
  bool moved_too_far(double t, const double* y) const;  // collective
  // Collective, reordering: whether the serial list would be rebuilt now (x_now_ current); if so its
  // positions and grid are taken for the local order.
  bool serial_list_stale();
  // Collective: the owned positions at (t, y), the largest h, and a halo plan when one is due.
  void prepare_local(double t, const double* y);
  void exchange_halo(const double* y);        // collective: the halo's state rows into halo_rows_
  void exchange_into_local(const double* y);  // collective: the owned and halo state into y_local_
  // Collective: the largest h of every rank's particles at y, and (with ghost walls) of the fluid alone.
  double largest_h(const double* y);
  // Collective, ghost walls only: how much farther than the support an image's source may lie (from the
  // owned positions now); the halo reaches that much farther per pass.
  double mirror_margin() const;
  void plan();                 // collective: halo plan and a new local system
  // Collective, at the start: a new partition by each owned particle's pair count, counted in the
  // local systems at the whole state's local part y (this rank's share of it).
  void balance_by_pairs(double t0, std::vector<double>& y);
  // Collective: the owned particles to `destination`, with y (this rank's state) and the `more`
  // per-particle arrays, all in the new share afterwards.
  void migrate_state(const std::vector<int>& destination, std::vector<double>& y, std::vector<std::vector<double>*> more);
  // Collective: f at (t, y) into ydot, and with `op` the viscous operator of the owned rows.
  void evaluate(double t, const double* y, double* ydot, ViscousOperator* op);

  // Per owned particle, `array` in this rank's state layout (L entries per particle block) as
  // columns, and back.
  void to_columns(const std::vector<double>& array, std::size_t blocks, std::vector<std::vector<double>>& columns) const;
  void from_columns(const std::vector<std::vector<double>>& columns, std::size_t blocks, std::vector<double>& array) const;
  void set_layout();
  // The particles of `whole` at `rows` (global ids first + row, ascending) become the owned ones,
  // with their per-owned arrays (extras()) and the layout.
  void take_particles(const SphSystem<D>& whole, const std::vector<std::uint32_t>& rows, std::size_t first);
  // `arrays` and the per-owned arrays that move with the particles (e_own_, h0_own_), for migrate().
  std::vector<std::vector<double>*> extras(std::vector<std::vector<double>*> arrays);
  // Blocks of n values in the state: positions, velocities and the optional per-particle fields.
  std::size_t state_blocks() const { return 2 * D + layout_.extra_blocks(); }

  Communicator comm_;
  Config config_;
  std::unique_ptr<RcbPartitioner<D>> rcb_;
  double rebalance_threshold_ = 0.0;
  bool replanned_ = false;        // a plan since the last imbalanced()
  bool plan_due_ = false;         // the owned particles changed: plan at the next evaluation
  std::vector<double> weight_;    // the owned rows' work, from imbalanced()
  Domain<D> domain_;
  double spacing_ = 0.0, range_ = 0.0, skin_ = 0.0;
  std::size_t n_fluid_global_ = 0;
  // Ghost walls: the whole system's mirrors, for every local system (none without ghost walls).
  std::optional<BoxWalls<D>> ghost_walls_;
  std::vector<GhostPlane<D>> ghost_planes_;
  double margin_ = 0.0, margin_plan_ = 0.0;  // mirror_margin() now and at the halo plan
  std::vector<double> e_own_;  // per owned particle: the scene's fixed e (walls; unused for the fluid)
  // Reordering: per owned particle its position at the serial list's latest rebuild, which orders the
  // local systems; that rebuild's support and Morton cell; whether there was one since the start or
  // since fluid last left the run.
  bool reorder_ = false;
  std::array<std::vector<double>, D> x_sorted_;
  double sorted_support_ = 0.0, sorted_cell_ = 0.0;
  bool sorted_once_ = false;
  // Variable h: h(0) of each owned particle; the largest h of the latest evaluation and of
  // the halo plan (the list radius, and the halo's reach, follow it); the kernel support per unit h.
  bool variable_h_ = false;
  std::vector<double> h0_own_;
  double hmax_ = 0.0, hmax_plan_ = 0.0, support_ = 0.0;
  double hmax_fluid_ = 0.0;  // the largest h of the fluid over all ranks (ghost walls with a variable h)
  Particles<D> owned_;
  std::vector<std::uint64_t> gid_;
  std::size_t nfo_ = 0;  // owned fluid particles
  StateLayout<D> layout_, whole_layout_;
  std::shared_ptr<const Halo<D>> halo_;
  std::shared_ptr<const VelocityHalo<D>> velocity_halo_;  // the halo columns of the current plan
  // Per local fluid particle: its owned row (or ViscousOperator::kNoRow) and its operator column.
  std::vector<std::uint32_t> local_row_, local_column_;
  ViscousOperator local_op_;
  std::vector<std::string> implicit_terms_;
  // The whole scene's step limits: a local system's viscous limit would be that of the liquids it
  // holds (the most viscous of its own and halo particles), and ranks holding different liquids would
  // step differently.
  CflLimits cfl_;
  std::size_t scene_particles_built_ = 0;
  // The owned rows of `source`, a state of layout W of the scene's particles [first, ...).
  std::vector<double> local_part(const std::vector<double>& source, const StateLayout<D>& W, std::size_t first) const;
  std::unique_ptr<SphSystem<D>> local_;
  std::vector<std::shared_ptr<Monitor<D>>> monitors_;  // the whole system's
  std::shared_ptr<bool> watching_ = std::make_shared<bool>(true);
  std::vector<std::uint32_t> owned_at_, halo_at_;  // local index of each owned / halo particle
  std::vector<std::uint64_t> local_gid_;          // global id of each local row
  std::size_t nf_local_ = 0;
  std::array<std::vector<double>, D> x_now_, x_plan_;  // owned positions now and at the plan
  std::vector<double> y_local_;    // the local state, made at output times (refresh_local)
  std::vector<double> halo_rows_;  // the halo's state rows of the latest exchange
  // The vectors made by wrap_state and their clones, while any lives (repartition() moves them).
  mutable std::vector<std::weak_ptr<VectorFamily>> families_;
  std::vector<double> initial_state_;  // take_initial_state()
  double stable_step_ = 0.0, first_stable_step_ = 0.0, widest_step_ = 0.0;
  long rhs_evals_ = 0;
  Stats stats_;
};

extern template class DistributedSystem<1>;
extern template class DistributedSystem<2>;
extern template class DistributedSystem<3>;

}  // namespace sphmol::parallel
