#pragma once
// A run split over several processes (sph-mol under mpirun in an MPI build): what the run loop
// (run/run_case.cpp) needs from the decomposition, declared here without MPI so that the serial
// library stays MPI-free. The implementation lives in lib/sphmol/parallel (parallel/mpi_run.hpp).
//
// The root rank builds the whole scene, and so does every rank for a case that cannot build a share
// of it (Case::build_share; user scenes can): the others build only the particles they start with.
// The integrator then advances each rank's own part of the state, and the ranks other than the root
// drop the scene's particles and the whole state once the partition has taken theirs
// (SphSystem::release_particles): what needs the whole scene later (the health limits' sums,
// checkpoints, the end) is computed or written on the root. At output times the case measures from each rank's own particles (owned_piece()), its sums
// and the conservation sums reduced exactly over the ranks (run/piece_reduction.hpp); observers that
// write per-rank files (VTK pieces) get those particles too, as do the probes at their own sampling
// times and at the output times, which combine the ranks' terms on the root. Only an observer that
// reads the whole system at output times (none ships) would have the whole state gathered there
// with the fields of each rank's own particles (whole_fields()), on the root, which writes the
// files and the summary as a serial run does, without evaluating the whole system.
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/core/scene_share.hpp"
#include "sphmol/rhs/sph_system.hpp"
#include "sphmol/run/health_limits.hpp"
#include "sphmol/run/owned_piece.hpp"
#include "sphmol/time/integrator.hpp"
#include "sphmol/time/ode_system.hpp"

namespace sphmol {

template <int D>
class PartitionedRun {
 public:
  virtual ~PartitionedRun() = default;
  // The system the integrator advances (this rank's particles) and its state vector.
  virtual OdeSystem& system() = 0;
  virtual std::vector<double>& state() = 0;
  // Collective: the whole state in the serial layout, on the root rank (the one that measures and
  // writes); the other ranks' `whole` is left as it was.
  virtual void gather(std::vector<double>& whole) = 0;
  // Collective: the elastic energy of the fluid at the latest evaluation (the first one, for the
  // health limits' budget), exact over the ranks (run/health_limits.hpp's elastic_energy_total).
  virtual double elastic_energy(const HealthLimits::Elastic& elastic) = 0;
  // Collective, at an output time t: the per-particle fields of the whole state at (t, state())
  // set on `whole` on the root rank (SphSystem::set_fields), from the ranks' evaluations of their
  // own particles: the whole system is never evaluated and never builds a neighbour list.
  virtual void whole_fields(double t, SphSystem<D>& whole) = 0;
  // Collective, at an output time or a probe sampling time t: this rank's own particles with their
  // fields at (t, state()), for the observers that write per-rank files or sample each rank's own
  // particles (probes with `every`). Valid until the next call on the run.
  virtual OwnedPiece<D> owned_piece(double t) = 0;
  // Collective: returns once every rank has called it.
  virtual void barrier() = 0;
  // Collective: the results of the case's monitors (rhs/monitor.hpp), which each rank gathers from
  // the evaluations of its own particles, combined over the ranks, on every rank: called before the
  // case reads them (output times, the summary).
  virtual void combine_monitors() = 0;
  // Collective, after each accepted step: throws BlowUp on every rank when any rank's part fails a
  // check (the same BlowUp everywhere). `signal`: the signal this rank has received (0: none);
  // returns the largest of all ranks', the same on every rank, so that the ranks stop at the same
  // step whichever of them a signal reached, and when (it travels in the check's own collective).
  virtual int check(double t, double h, int signal) = 0;
  // Outflow (run/outflow.hpp): the fluid particles the latest check found outside the domain, not
  // taken out yet, by global id (the whole system's state index), ascending, the same on every rank
  // (empty: none). take_out(gone), between steps on every rank: this rank's own ones get zero
  // velocities in state(), and they and their halo copies leave every pair from the next evaluation on.
  virtual const std::vector<std::size_t>& leavers() const = 0;
  virtual const std::vector<double>& leaver_masses() const = 0;  // theirs, in the same order
  virtual void take_out(const std::vector<std::size_t>& gone) = 0;
  // Collective, before the first check: the physical bounds (run/health_limits.hpp), the serial
  // run's, from the state at t0 the run starts from.
  virtual void start_health_check(double t0, const HealthLimits& limits) = 0;
  // Collective, after check() threw: the last state that passed the checks, whole in the serial
  // layout, on the root (which writes it as the serial run does, run/last_good_state.hpp).
  virtual void gather_last_good(std::vector<double>& whole) = 0;
  // Collective: the largest of the ranks' `signal` (0: none), where no step is taken (after the last).
  virtual int largest_signal(int signal) = 0;
  // Collective, between steps (t: the time reached): moves particles between ranks when the load
  // has drifted out of balance, with the integrator's own state, and starts the integrator again
  // on the new share (state() changes then).
  virtual void rebalance(Integrator& integrator, double t) = 0;
  // Checkpoints: the integrator's state (save_state()) with its per-particle arrays in the serial
  // layout of the whole state (collective; whole on the root, which writes the checkpoint), and this rank's part of such a state
  // (for restore_state()), so that a checkpoint is the same whatever rank count writes or reads it.
  virtual nlohmann::json whole_integrator_state(const nlohmann::json& state) = 0;
  virtual nlohmann::json local_integrator_state(const nlohmann::json& whole) = 0;
  virtual double last_good_time() const = 0;
  // Run counters of this rank: seconds in the RHS and in its neighbour search, list rebuilds.
  virtual double rhs_seconds() const = 0;
  virtual double search_seconds() const = 0;
  virtual long neighbor_rebuilds() const = 0;
  // The summary's "parallel" object (ranks, halo sizes, exchange time, load imbalance).
  virtual nlohmann::json describe() const = 0;
};

// Splits a run over the ranks; set in RunOptions by a program started under MPI.
class RunPartitioner {
 public:
  virtual ~RunPartitioner() = default;
  // The rank that writes files and the summary.
  virtual bool root() const = 0;
  // This rank's share of the scene, SceneShare{rank, ranks}: a case that builds shares
  // (Case::build_share) builds only it on every rank but the root, which keeps the whole scene. And
  // the collectives over the ranks, for the set-up's sums and gathers before the partition
  // (run/start_piece.hpp).
  virtual SceneShare share() const = 0;
  virtual PieceCollectives collectives() const = 0;
  // Collective. `whole`: the scene as built on this rank, whole or this rank's share
  // (SphSystem::is_share); (t0, y0) the state the run starts from, of `whole`'s particles (whole's
  // own layout). Throws ConfigError on every rank for a configuration the partitioned run does not
  // support.
  virtual std::unique_ptr<PartitionedRun<1>> partition(const Config& config, const SphSystem<1>& whole,
                                                       const std::vector<double>& y0, double t0,
                                                       const std::function<void()>& scene_read = {}) const = 0;
  virtual std::unique_ptr<PartitionedRun<2>> partition(const Config& config, const SphSystem<2>& whole,
                                                       const std::vector<double>& y0, double t0,
                                                       const std::function<void()>& scene_read = {}) const = 0;
  virtual std::unique_ptr<PartitionedRun<3>> partition(const Config& config, const SphSystem<3>& whole,
                                                       const std::vector<double>& y0, double t0,
                                                       const std::function<void()>& scene_read = {}) const = 0;
};

}  // namespace sphmol
