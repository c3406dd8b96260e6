#pragma once
// A case's measurement taken at every RHS evaluation (every step and stage), not only at output
// times: the dam break's wall penetrations, the water column's drift. A case declares it once
// (SphSystem::add_monitor); the monitor then makes a term that watches the scene's own system and,
// in a run over MPI ranks, one for each rank's local system (owned and halo particles,
// parallel/distributed_system.hpp), which watches the fluid particles the rank owns. Its results
// live in the monitor, keyed by each particle's serial index (its global id over ranks), so they
// outlast the local systems, which are made again at every halo plan, and the particles' moves
// between ranks. combine() merges the ranks' results where the case reads them (output times, the
// summary): exact reductions only (rhs/rank_reduction.hpp), so the run over ranks reports the
// serial run's values.
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "sphmol/rhs/rank_reduction.hpp"
#include "sphmol/rhs/term.hpp"

namespace sphmol {

// The fluid rows of a system that a monitor's term watches.
struct WatchedRows {
  // Per fluid row: the particle's serial index and whether this rank owns it (a halo copy is
  // watched by its owner, so that no particle counts twice). Both empty: the scene's own system,
  // whose rows are the serial indices (through Workspace::order when reordered), all watched.
  std::vector<std::uint64_t> id;
  std::vector<std::uint8_t> owned;
  // A rank's local system: per fluid row, its particle's position as the scene was built (D values a
  // row, row after row), which travels with the particle between ranks; so a monitor that compares
  // with the start keeps no copy of the whole scene's starts on a rank that dropped the scene.
  std::vector<double> start;
  // When set and false, the term watches nothing: evaluations that are not the run's own (an
  // integrator starting again on a rank's new share evaluates a state the serial run never does).
  std::shared_ptr<const bool> watching;

  bool whole() const { return id.empty(); }
  bool paused() const { return watching && !*watching; }
};

template <int D>
class Monitor {
 public:
  virtual ~Monitor() = default;
  // The term that watches `rows` of a system at every evaluation, adding to this monitor's results.
  virtual std::unique_ptr<Term<D>> watch(const WatchedRows& rows) = 0;
  // Collective over the ranks: every rank's results merged, on every rank.
  virtual void combine(const RankReduction& ranks) = 0;
  // The scene's own system dropped its particles (SphSystem::release_particles, on the ranks other
  // than 0 of a run over ranks): drop what the monitor keeps per particle of the whole scene. Its
  // terms for local systems read what they need from WatchedRows.
  virtual void release_whole() {}
};

}  // namespace sphmol
