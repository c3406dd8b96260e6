#pragma once
// Writes the `probes` of a config (probes/probe_config.hpp): one CSV per probe, probe_<name>.csv,
// with one header row naming each column and its unit and no other non-data line. Point, line and
// plane probes hold the Shepard-interpolated fluid fields (fluid_sampler.hpp; an empty cell where no
// fluid particle is within the kernel support), height gauges the free-surface height
// (height_gauge.hpp), force probes the force of the fluid on a wall body (wall_force.hpp). A probe
// samples at the output times (and t = 0), or every `every` seconds from t = 0, when the run loop
// stops for it (next_time / at_time); over ranks both from the ranks' own particles (below). The
// files go through OutputSink::write (atomic, in the run's ledger); the rows so far are the
// observer's checkpoint state, so a restart continues each series.
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "sphmol/probes/height_gauge.hpp"
#include "sphmol/probes/probe_config.hpp"
#include "sphmol/probes/wall_force.hpp"
#include "sphmol/run/case.hpp"
#include "sphmol/run/whole_piece.hpp"

namespace sphmol {

template <int D>
class ProbeObserver final : public OutputObserver<D> {
 public:
  // Checks each probe against the built scene: a sample point or gauge line outside the particles'
  // bounding box widened by the kernel support is a ConfigError at the probe's key (FILE:LINE).
  // The only call that reads sys.particles(): it copies the force probes' walls (BodyWalls). Over
  // ranks, the piece methods read of `whole` only its domain; the rank's own system gives the rest.
  // A serial run: the whole scene at its initial state.
  ProbeObserver(const Config& config, const SphSystem<D>& sys);
  // Over ranks (collective): `start` is the rank's particles as the run starts (run/start_piece.hpp);
  // the probes' checks see the whole scene (its box, the force probes' bodies) and each force probe
  // keeps the body's walls, gathered from the ranks, without a rank holding the whole scene.
  ProbeObserver(const Config& config, const OwnedPiece<D>& start);

  void at_output(const SphSystem<D>& sys, const double* y, double t, const OutputSink& out) override;
  // Only the probes without `every` sample at the output times.
  bool samples_outputs() const override {
    for (const auto& s : series_)
      if (!s.cfg.every) return true;
    return false;
  }
  void at_stop(const OutputSink& out) override;
  double next_time() const override;
  void at_time(const SphSystem<D>& sys, const double* y, double t, const OutputSink& out) override;
  void pass_time(double t) override { due(t); }
  // Over ranks, at the `every` probes' times (at_time_pieces) and, for the probes without `every`,
  // at the output times and t = 0 (at_output_time_pieces): each rank's terms of the serial sums
  // (the kernel weights and values of its own fluid near each sample point, the force pairs of its
  // own fluid with the body's walls) go to rank 0, which adds them in the serial order (by cell and
  // global id, as the serial bins visit them; by fluid particle, then wall), so the files are the
  // serial run's to the bit, without gathering the whole state.
  bool samples_pieces() const override { return true; }
  void at_time_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t, const OutputSink& out) override;
  bool samples_output_pieces() const override { return true; }
  void at_output_time_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t, const OutputSink& out) override;
  nlohmann::json save_state() const override;
  void restore_state(const nlohmann::json& state, const OutputSink& out) override;
  std::vector<PlotScript> plots(const OutputSink& out) const override;
  void annotate(nlohmann::json& summary) const override;

  // Called with every sample's values as its rows are made of them (probe name, t, values in the
  // order of the row's columns): for tests that compare them bit for bit, which the files' 12
  // digits do not show.
  std::function<void(const std::string&, double, const std::vector<double>&)> on_sample;

  // The file a probe writes.
  static std::string file_name(const std::string& probe) { return "probe_" + probe + ".csv"; }

 private:
  struct Series {
    ProbeConfig cfg;
    std::vector<geometry::Vec<D>> points;  // point, line, plane
    double bottom = 0.0, top = 0.0;        // height gauge: the scanned vertical range
    std::string header, rows, description;
    long next_k = 0;                       // `every` probes: index of the next sample time k * every
    bool dirty = false;                    // rows not yet in the file
    std::size_t walls = 0;                 // force: the body's entry in walls_; height gauge: every wall's
  };
  double sample_time(const Series& s, long k) const;
  // The `every` series with a sample time at t (within round-off), moved past it.
  std::vector<std::size_t> due(double t);
  void sample(const std::vector<std::size_t>& which, const SphSystem<D>& sys, const double* y, double t);
  // The same series from the ranks' pieces (collective: every rank passes the same `which`).
  void sample_pieces(const std::vector<std::size_t>& which, const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t);
  std::vector<std::size_t> at_outputs() const;  // the series without `every`
  // Every wall's kernel sum at t when a height gauge is among `which` (all gauges share the walls of
  // every body, walls_), else null: built once per sample time.
  std::unique_ptr<WallKernelSum<D>> gauge_walls(const std::vector<std::size_t>& which, double t, const Domain<D>& domain) const;
  // The sampled values of one row group (point, line, plane: columns() per point; height gauge: 1;
  // force: D) as the series' rows at t.
  void append_rows(Series& s, double t, const std::vector<double>& values);
  static std::size_t columns(const Series& s);
  static geometry::Vec<D> gauge_line(const Series& s);  // a height gauge's line (vertical coordinate 0)
  void flush(const OutputSink& out);

  std::vector<Series> series_;
  // The walls of each probed body (and every wall, for the height gauges), copied at construction:
  // over ranks the probes read these,
  // and no per-particle array of the whole scene, which the ranks other than 0 drop after the set-up.
  std::vector<BodyWalls<D>> walls_;
  std::vector<double> output_times_;
  double t_end_ = 0.0, h_ = 0.0, support_ = 0.0;
  double (*W_)(double, double) = nullptr;
  double (*dWdr_)(double, double) = nullptr;
  WallForceModel model_;
  double last_flush_ = -std::numeric_limits<double>::infinity();  // steady-clock seconds
};

}  // namespace sphmol
