#pragma once
// A verification case: builds its scene and RHS from the config, and measures the solution against
// its reference at output times. Cases register by name (run/case_registry.hpp); the generic run
// loop (run/run_case.cpp) integrates and calls the case and every output observer at output times.
#include <memory>
#include <stdexcept>
#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/core/scene_share.hpp"
#include "sphmol/rhs/sph_system.hpp"
#include "sphmol/run/owned_piece.hpp"
#include "sphmol/run/whole_piece.hpp"

namespace sphmol {

// Where a run writes its files; `enabled` is false for in-memory runs (tests, studies). Every file
// the run writes goes through write() (or is recorded with record()), so the run knows its own files:
// the summary lists them, plots read only them, and --overwrite deletes exactly them. Copies of a sink
// share one list.
struct OutputSink {
  std::string directory;
  bool enabled = true;
  std::shared_ptr<std::vector<std::string>> files = std::make_shared<std::vector<std::string>>();
  std::string path(const std::string& file) const { return directory + "/" + file; }
  // Writes DIRECTORY/file atomically (io/atomic_file.hpp) and records it.
  void write(const std::string& file, const std::string& content) const;
  // Records a file or directory (a name inside DIRECTORY) written some other way.
  void record(const std::string& file) const;
  // Names recorded so far, in the order first written, each once.
  const std::vector<std::string>& written() const { return *files; }
};

// One plot: `png` is the file name in the output directory; `script` is gnuplot input that reads
// the run's files (paths relative to the output directory) and writes `png`.
struct PlotScript {
  std::string png;
  std::string script;
};

template <int D>
class Case {
 public:
  virtual ~Case() = default;
  // Builds the particles, domain and RHS. Called once.
  virtual std::unique_ptr<SphSystem<D>> build(const Config& config) = 0;
  // A run over ranks: whether the case can build a share of its scene alone, and that build (instead
  // of build(); called once): the system of the share's particles (SphSystem::set_whole_scene), with
  // the case's whole-scene quantities (velocity scale, ...) as build() sets them, computed without
  // holding the whole scene.
  virtual bool builds_shares() const { return false; }
  virtual std::unique_ptr<SphSystem<D>> build_share(const Config& config, SceneShare share) {
    throw std::logic_error("Case::build_share: the case builds the whole scene only");
  }
  // Name of the reference solution (for the summary).
  virtual std::string reference() const = 0;
  // Error measures at an output time, under the documented keys of the case (e.g. e_rms, e_max).
  // May write per-time files (profiles) through `out`. A case that measures from pieces measures
  // the whole system as one piece (run/whole_piece.hpp).
  virtual nlohmann::json measure(const SphSystem<D>& sys, const double* y, double t, const OutputSink& out) {
    if (!measures_pieces()) throw std::logic_error("Case: measure() not implemented");
    return measure_pieces(sys, whole_piece(sys, y), t, out);
  }
  // Whether the case measures from pieces: over several ranks measure_pieces() is then called on
  // every rank with the rank's own particles (run/owned_piece.hpp), and its sums reduce over the
  // ranks exactly (run/piece_reduction.hpp), so that no whole state is gathered for it and the
  // measurement is the serial one to the bit. `whole`: the scene as built (its fields and state are
  // not the output time's off rank 0); `out`: the run's sink, enabled on rank 0 only. Returns the
  // measurement on every rank; a BlowUp it throws must be thrown on every rank alike.
  virtual bool measures_pieces() const { return false; }
  virtual nlohmann::json measure_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t, const OutputSink& out) {
    throw std::logic_error("Case: measure_pieces() not implemented");
  }
  // The summary's final_errors; by default the last measurement without its "t".
  virtual nlohmann::json final_errors(const nlohmann::json& errors) const {
    if (errors.empty()) return nlohmann::json::object();
    nlohmann::json last = errors.back();
    last.erase("t");
    return last;
  }
  // The final_errors key that studies (compare, converge, stability) use as "the error".
  virtual std::string primary_error() const { return "e_rms"; }
  // Whether primary_error() is an error against an exact reference (true), or a quantity of the
  // flow (a probe value, a conserved quantity) that the studies compare with a finer run: against a
  // reference run at a small step (compare, converge --refine time) or the next finer spacing
  // (converge --refine space).
  virtual bool has_exact_reference() const { return true; }
  // The scene's velocity scale U [m/s] that the health check bounds speeds and densities by (0: none,
  // e.g. a shock tube, whose supersonic speeds are the physics), and whether the fluid has a free
  // surface (its density may then fall below rho0 freely). Read after build().
  virtual double velocity_scale(const Config& config) const { return 0.0; }
  virtual bool free_surface() const { return false; }
  // Anything else the case adds to the summary (reference parameters, wave positions, ...).
  virtual void annotate(nlohmann::json& summary) const {}
  // Plots made after the run (run/plots.hpp): gnuplot scripts, each writing one PNG in the output
  // directory. Empty by default; a case adds its own (ChannelCase: profiles vs the exact solution).
  virtual std::vector<PlotScript> plots(const OutputSink& out) const { return {}; }
  // Carried through checkpoints, as OutputObserver's state is: what the case accumulates over the
  // output times (a series it writes whole at every output, running maxima of its monitors), so that
  // a restarted run writes the same files and summary as an uninterrupted one. Doubles as text of
  // their bits (io/double_codec.hpp): exact, and NaN/inf survive. Empty (the default): nothing to
  // carry. restore_state() is called on every rank after the first evaluation at the checkpoint's
  // state (whose monitors have already run: merge, do not overwrite) and before any measurement;
  // a malformed state throws (std::exception), which the run reports as a bad checkpoint.
  virtual nlohmann::json save_state() const { return nlohmann::json::object(); }
  virtual void restore_state(const nlohmann::json& state) {}
};

// Called at every output time after the case's measurement (VTK writers, checkpoints, ...).
template <int D>
class OutputObserver {
 public:
  virtual ~OutputObserver() = default;
  virtual void at_output(const SphSystem<D>& sys, const double* y, double t, const OutputSink& out) = 0;
  // Whether at_output reads the state (over several ranks the whole state is then gathered on rank 0
  // at output times for it, unless it writes pieces or samples the output times from pieces); false
  // for an observer that only samples at its own times (probes that all have `every`).
  virtual bool samples_outputs() const { return true; }
  // The run stops: at t_end, by a signal or at a blow-up. Writes what was sampled since the last write
  // (on rank 0), so that a run that ends early leaves its series up to where it stopped.
  virtual void at_stop(const OutputSink& out) {}
  // Over several ranks: an observer that writes per-rank files (VTK pieces) is called on every rank
  // at output times with the rank's own particles (run/owned_piece.hpp) instead of at_output on
  // rank 0 with the whole system. `whole`: the scene as built (not evaluated off rank 0); `out`:
  // enabled on every rank when the run writes files, rank 0's records being the run's file list.
  virtual bool writes_pieces() const { return false; }
  virtual void at_output_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t, const OutputSink& out) {}
  // An observer with its own sampling times (probes with `every`): the earliest time it still wants
  // (infinity: none); the run loop stops there too and calls at_time (after refresh_fields).
  virtual double next_time() const { return std::numeric_limits<double>::infinity(); }
  virtual void at_time(const SphSystem<D>& sys, const double* y, double t, const OutputSink& out) {}
  // Over several ranks an observer that samples_pieces() is called at its own times on every rank,
  // with the rank's own particles at (t, the state), instead of at_time on rank 0 with the whole
  // system: no whole state is gathered for it. `out` is the run's sink (enabled on rank 0 only).
  virtual bool samples_pieces() const { return false; }
  virtual void at_time_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t, const OutputSink& out) {}
  // Over several ranks an observer that samples_outputs() and samples_output_pieces() is called at
  // output times (and t = 0) on every rank with the rank's own particles at (t, the state), instead
  // of at_output on rank 0 with the whole system (probes without `every`): no whole state is
  // gathered for it. `out` is the run's sink (enabled on rank 0 only).
  virtual bool samples_output_pieces() const { return false; }
  virtual void at_output_time_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t, const OutputSink& out) {}
  // Over several ranks, on the ranks other than 0 (which alone calls at_time): the sampling times
  // up to t pass as at_time passes them, without a sample, so that next_time() and with it the
  // times the run stops at stay the same on every rank.
  virtual void pass_time(double t) {}
  // Plots made after the run (next to the case's), and what its files hold (the summary's csv_files).
  virtual std::vector<PlotScript> plots(const OutputSink& out) const { return {}; }
  virtual void annotate(nlohmann::json& summary) const {}
  // Carried through checkpoints, so a restarted run continues the observer (e.g. the .pvd list).
  virtual nlohmann::json save_state() const { return nlohmann::json::object(); }
  virtual void restore_state(const nlohmann::json& state, const OutputSink& out) {}
};

}  // namespace sphmol
