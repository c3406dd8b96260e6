#include "sphmol/cases/channel/channel_case.hpp"
#include "sphmol/cases/channel/channel_settings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sphmol/run/gnuplot_preamble.hpp"
#include "sphmol/run/gathered_rows.hpp"
#include "sphmol/run/piece_reduction.hpp"
#include "sphmol/io/atomic_file.hpp"
#include "sphmol/run/timed_output_files.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/cases/channel/channel_scene.hpp"
#include "sphmol/time/blow_up.hpp"

namespace sphmol {

std::unique_ptr<SphSystem<2>> ChannelCase::build(const Config& config) {
  ChannelScene scene = build_channel_scene(config);
  ref_ = make_channel_reference(config);
  profiles_ = config.output.profiles;
  wall_layers_ = scene.wall_layers;
  spacing_ = scene.spacing;
  height_ = config.settings<ChannelSettings>().channel_height;
  return assemble_system<2>(config, std::move(scene.particles), scene.domain, scene.spacing);
}

namespace {

// One fluid particle's row of a profile file, with its global id (the order of equal heights).
struct ProfileRow {
  std::int64_t id;
  double y, u_sph, u_exact;
};

}  // namespace

nlohmann::json ChannelCase::measure_pieces(const SphSystem<2>& whole, const OwnedPiece<2>& piece, double t,
                                           const OutputSink& out) {
  const auto& L = piece.system->layout();
  const double* y = piece.y;
  // A fluid particle pushed into the wall layers (the health check allows them: they are inside the
  // domain) has no reference value: that run has blown up (stability studies near the step limit).
  // Tested here by position, so that any other error of the reference stays an error. The particle
  // named is the one of smallest id, as the serial scan finds it, on every rank.
  {
    PieceReduction inside;
    const auto first = inside.smallest();
    for (std::size_t k = 0; k < piece.fluid_rows.size(); ++k) {
      const double yi = y[L.position(1) + piece.fluid_rows[k]];
      if (!(yi >= 0.0 && yi <= height_)) inside.add(first, static_cast<double>(piece.fluid_ids[k]));
    }
    inside.reduce(piece);
    if (std::isfinite(inside.value(first))) {
      const auto id = static_cast<std::int64_t>(inside.value(first));
      PieceReduction where;  // its height, from the rank that owns it
      const auto height = where.largest();
      for (std::size_t k = 0; k < piece.fluid_rows.size(); ++k)
        if (piece.fluid_ids[k] == id) where.add(height, y[L.position(1) + piece.fluid_rows[k]]);
      where.reduce(piece);
      throw BlowUp(t, static_cast<long>(id), "fluid particle inside a wall (y = " + std::to_string(where.value(height)) +
                                                " m, channel [0, " + std::to_string(height_) + "] m)");
    }
  }
  // Exact sums over the ranks' own fluid (run/piece_reduction.hpp): the serial values to the bit.
  // e_rms and e_max are relative to the speed |v0|, so a flow driven along -x (negative plate speed or
  // body force) scores as its mirror image along +x. e_signed: the signed mean error / v0, positive
  // where the fluid runs ahead of the reference in the flow direction (also mirror-invariant); its
  // sign changes over time reveal the oscillation about the reference (Vukčević 2012, §9, Vukčević
  // et al. 2012, §5) that the stability study classifies.
  const double speed = std::abs(ref_.v0);
  PieceReduction r;
  const auto count = r.sum(), squares = r.sum(), signed_sum = r.sum(), largest = r.largest();
  std::vector<ProfileRow> rows;
  // The profile file lists every fluid particle: written only when the run writes files (on rank 0).
  const bool profile = profiles_ && writes_files(piece, out.enabled);
  if (profile) rows.reserve(piece.fluid_rows.size());
  for (std::size_t k = 0; k < piece.fluid_rows.size(); ++k) {
    const std::size_t i = piece.fluid_rows[k];
    const double yi = y[L.position(1) + i];
    const double u = y[L.velocity(0) + i];
    const double ue = ref_.velocity(yi, t);
    const double err = std::abs(u - ue) / speed;
    r.add(count, 1.0);
    r.add(squares, err * err);
    r.add(largest, err);
    r.add(signed_sum, u - ue);
    if (profile) rows.push_back({piece.fluid_ids[k], yi, u, ue});
  }
  r.reduce(piece);
  const double n = r.value(count);
  const double e_rms = n > 0.0 ? std::sqrt(r.value(squares) / n) : 0.0;
  const double e_max = std::max(0.0, r.value(largest));
  const double e_signed = n > 0.0 ? r.value(signed_sum) / (n * ref_.v0) : 0.0;
  if (profile) {
    // Every rank's rows on rank 0, sorted by height (equal heights by id, whatever the ranks).
    rows = gather_rows(piece, rows);
    std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.y < b.y || (a.y == b.y && a.id < b.id); });
    if (out.enabled) {
      std::ostringstream s, name;
      s << "y [m],u_sph [m/s],u_exact [m/s]\n" << std::setprecision(12);
      for (const auto& p : rows) s << p.y << ',' << p.u_sph << ',' << p.u_exact << '\n';
      name << "profile_t" << output_time_text(t) << ".csv";
      out.write(name.str(), s.str());
    }
  }
  return {{"t", t}, {"e_rms", e_rms}, {"e_max", e_max}, {"e_signed", e_signed}};
}

void ChannelCase::annotate(nlohmann::json& summary) const {
  summary["v0"] = ref_.v0;
  summary["discretization"]["spacing"] = spacing_;
  summary["discretization"]["wall_layers"] = wall_layers_;
  if (profiles_)
    summary["csv_files"]["profile_t<t>.csv"] = "SPH velocity profile across the channel (fluid particles) vs " + ref_.name +
                                               " at output time t";
}

std::vector<PlotScript> ChannelCase::plots(const OutputSink& out) const {
  if (!profiles_) return {};
  const auto files = timed_output_files(out, "profile_t");
  if (files.empty()) return {};
  std::ostringstream s;
  s << gnuplot_csv_preamble("SPH velocity profiles vs " + ref_.name + " (sph-mol ChannelCase)", 900, 640, 11, "profiles.png")
    << "set title \"" << ref_.name << ": u(y) at the output times; points SPH, lines exact\" noenhanced\n"
    << "set xlabel 'u [m/s]'\nset ylabel 'y [m]'\nset key outside right top\nset grid\n"
    << "plot \\\n";
  for (std::size_t i = 0; i < files.size(); ++i) {
    const auto& [t, f] = files[i];
    s << "  '" << f << "' using 2:1 with points pt 7 ps 0.6 lc " << i + 1 << " title 't = " << t << " s', \\\n"
      << "  '" << f << "' using 3:1 with lines lw 1.5 lc " << i + 1 << " notitle"
      << (i + 1 < files.size() ? ", \\\n" : "\n");
  }
  return {{"profiles.png", s.str()}};
}

double ChannelCase::velocity_scale(const Config& config) const {
  if (config.settings<ChannelSettings>().couette) return std::abs(config.settings<ChannelSettings>().wall_velocity);
  double g = 0.0;
  for (double x : config.fluid.body_force) g += x * x;
  const double l = config.settings<ChannelSettings>().channel_height, nu = config.fluid.kinematic_viscosity;
  return nu > 0.0 ? std::sqrt(g) * l * l / (8.0 * nu) : 0.0;
}

}  // namespace sphmol
