#include "sphmol/cases/hydrostatic/hydrostatic_case.hpp"
#include "sphmol/cases/hydrostatic/hydrostatic_settings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "sphmol/run/gathered_rows.hpp"
#include "sphmol/run/case_state.hpp"
#include "sphmol/run/gnuplot_preamble.hpp"
#include "sphmol/run/piece_reduction.hpp"
#include "sphmol/analysis/drift_monitor.hpp"
#include "sphmol/io/atomic_file.hpp"
#include "sphmol/run/timed_output_files.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/scenes/box_scene.hpp"

namespace sphmol {

template <int D>
std::unique_ptr<SphSystem<D>> HydrostaticCase<D>::build(const Config& config) {
  const auto& box = config.settings<HydrostaticSettings>().box;  // [width, (breadth,) depth]
  if (static_cast<int>(box.size()) != D) throw std::invalid_argument("geometry.box: needs one length per dimension");
  depth_ = box[D - 1];
  rho0_ = config.fluid.density;
  g_ = -config.fluid.body_force[D - 1];
  bool along_last = g_ > 0.0;
  for (int d = 0; d + 1 < D; ++d) along_last = along_last && config.fluid.body_force[d] == 0.0;
  if (!along_last)
    throw std::invalid_argument("fluid.body_force: hydrostatic needs gravity along the last axis, pointing down, g > 0");
  settle_ = 2.0 * config.fluid.body_force_ramp;
  profiles_ = config.output.profiles;
  BoxWalls<D> walls{};
  for (int d = 0; d < D; ++d) walls[d][0].present = walls[d][1].present = true;
  walls[D - 1][1].present = false;  // open top: free surface
  const double width = box[0];
  const double dx0 = config.discretization.particles_across > 0 ? width / config.discretization.particles_across
                                                                : config.discretization.spacing;
  std::array<double, D> tank{};
  for (int d = 0; d < D; ++d) tank[d] = box[d];
  tank[D - 1] = std::round(1.2 * depth_ / dx0) * dx0;
  BoxSceneOf<D> s = build_box_scene<D>(config, tank, depth_, walls, false);
  spacing_ = s.spacing;
  // The monitor copies the fluid's start positions (not a copy of the whole particle set).
  auto drift = std::make_shared<DriftMonitor<D>>(s.particles, drift_);
  auto sys = assemble_system<D>(config, std::move(s.particles), s.domain, s.spacing, &s.walls);
  sys->add_monitor(std::move(drift));
  return sys;
}

namespace {

// One fluid particle's row of a pressure file, with its global id (the file's order).
struct PressureRow {
  std::int64_t id;
  double y, p, p_exact;
};

}  // namespace

template <int D>
nlohmann::json HydrostaticCase<D>::measure_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t,
                                                  const OutputSink& out) {
  const auto& lay = piece.system->layout();
  const double* y = piece.y;
  const auto& p = piece.system->pressure();
  const auto& rho = piece.system->density();
  const double scale = rho0_ * g_ * depth_;
  // Exact sums over the ranks' own fluid (run/piece_reduction.hpp): the serial values to the bit.
  // Least-squares line p = a + b y through every fluid particle: b against -rho0 g is the fitted
  // gradient's error (a column whose pressure is right on average can still lean).
  PieceReduction r;
  const auto count = r.sum(), s2 = r.sum(), sy = r.sum(), sp = r.sum(), syy = r.sum(), syp = r.sum(), srho = r.sum();
  const auto emax = r.largest();
  const bool file = profiles_ && writes_files(piece, out.enabled);
  std::vector<PressureRow> rows;
  for (std::size_t k = 0; k < piece.fluid_rows.size(); ++k) {
    const std::size_t i = piece.fluid_rows[k];
    const double yi = y[lay.position(D - 1) + i];
    const double pe = rho0_ * g_ * (depth_ - yi);
    const double e = (p[i] - pe) / scale;
    r.add(count, 1.0);
    r.add(s2, e * e);
    r.add(emax, std::abs(e));
    r.add(sy, yi);
    r.add(sp, p[i]);
    r.add(syy, yi * yi);
    r.add(syp, yi * p[i]);
    r.add(srho, rho[i]);
    if (file) rows.push_back({piece.fluid_ids[k], yi, p[i], pe});
  }
  r.reduce(piece);
  if (file) {
    // Every rank's rows on rank 0, in the order of the particles.
    rows = gather_rows(piece, rows);
    std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
    if (out.enabled) {
      std::ostringstream csv, name;
      csv << (D == 3 ? "z [m]" : "y [m]") << ",p_sph [Pa],p_exact [Pa]\n" << std::setprecision(10);
      for (const auto& row : rows) csv << row.y << ',' << row.p << ',' << row.p_exact << '\n';
      name << "pressure_t" << output_time_text(t) << ".csv";
      out.write(name.str(), csv.str());
    }
  }
  const double nn = r.value(count), var = r.value(syy) - r.value(sy) * r.value(sy) / nn;
  const double slope = var > 0.0 ? (r.value(syp) - r.value(sy) * r.value(sp) / nn) / var : 0.0;
  return {{"t", t}, {"settled", t >= settle_}, {"p_rms", std::sqrt(r.value(s2) / nn)}, {"p_max", std::max(0.0, r.value(emax))},
          {"gradient_rel_error", -slope / (rho0_ * g_) - 1.0},
          // Against the column's own weight, g times its mean density: the weakly compressible fluid is
          // denser than rho0 under load (by g H / c0^2 = 1 % at the bottom with c0 = 10 sqrt(g H)), so
          // its exact gradient is steeper than rho0 g; this part is the discretisation's alone.
          {"gradient_rel_error_eos", -slope / (g_ * r.value(srho) / nn) - 1.0}, {"max_drift", *drift_ / spacing_}};
}

// Worst over the settled output times: the errors must stay bounded, not only end small.
template <int D>
nlohmann::json HydrostaticCase<D>::final_errors(const nlohmann::json& errors) const {
  double prms = 0.0, pmax = 0.0, grad = 0.0, grad_eos = 0.0;
  int settled = 0;
  for (const auto& e : errors)
    if (e["settled"].get<bool>()) {
      prms = std::max(prms, e["p_rms"].get<double>());
      pmax = std::max(pmax, e["p_max"].get<double>());
      if (e.contains("gradient_rel_error") && std::abs(e["gradient_rel_error"].get<double>()) > std::abs(grad))
        grad = e["gradient_rel_error"].get<double>();
      if (e.contains("gradient_rel_error_eos") && std::abs(e["gradient_rel_error_eos"].get<double>()) > std::abs(grad_eos))
        grad_eos = e["gradient_rel_error_eos"].get<double>();
      ++settled;
    }
  nlohmann::json f = {{"max_drift", *drift_ / spacing_}, {"settled_outputs", settled}};
  // Creep: how far the largest displacement grew over the second half of the run (spacings). A lattice
  // that only compresses under its weight stops moving once settled (0); one that rearranges keeps growing.
  if (!errors.empty()) {
    const double t_last = errors.back()["t"].get<double>();
    for (const auto& e : errors)
      if (e["t"].get<double>() >= 0.5 * t_last) {
        f["drift_creep"] = errors.back()["max_drift"].get<double>() - e["max_drift"].get<double>();
        f["drift_creep_since"] = e["t"];
        break;
      }
  }
  if (settled > 0) {
    f["p_rms"] = prms;
    f["p_max"] = pmax;
    f["gradient_rel_error"] = grad;
    f["gradient_rel_error_eos"] = grad_eos;
  } else {
    f["p_rms"] = nullptr;
    f["p_max"] = nullptr;
    f["gradient_rel_error"] = nullptr;
    f["gradient_rel_error_eos"] = nullptr;
  }
  return f;
}

template <int D>
void HydrostaticCase<D>::annotate(nlohmann::json& summary) const {
  summary["settle_time"] = settle_;
  summary["final_errors_note"] = "p_rms, p_max, gradient_rel_error (least-squares slope of p against height over -rho0 g, minus 1; "
      "signed, largest magnitude; gradient_rel_error_eos: the same against -g times the mean density, the "
      "exact gradient of the weakly compressible column): worst over output times t >= settle_time; max_drift over all RHS evaluations; "
      "drift_creep: growth of max_drift from the first output at t >= t_last / 2 (drift_creep_since) to the last";
  summary["discretization"]["spacing"] = spacing_;
  if (profiles_)
    summary["csv_files"]["pressure_t<t>.csv"] =
        std::string("pressure of every fluid particle vs the hydrostatic p = rho0 g (depth - ") + (D == 3 ? "z" : "y") +
        ") at output time t";
}

// p against depth at the last output time: every fluid particle, and the line rho0 g depth.
template <int D>
std::vector<PlotScript> HydrostaticCase<D>::plots(const OutputSink& out) const {
  const auto files = timed_output_files(out, "pressure_t");
  if (files.empty()) return {};
  const auto& [t_last, file] = files.back();
  std::ostringstream s;
  s << std::setprecision(10)
    << gnuplot_csv_preamble("hydrostatic column: p vs depth (sph-mol HydrostaticCase)", 800, 640, 11, "pressure_depth.png")
    << "set title \"hydrostatic pressure at t = " << t_last << " s\"\n"
    << "set xlabel 'depth H - " << (D == 3 ? "z" : "y") << " [m]'\nset ylabel 'p [Pa]'\nset key top left\nset grid\n"
    << "H = " << depth_ << "\nrho0g = " << rho0_ * g_ << "\nset xrange [0:H]\n"
    << "plot '" << file << "' using (H - $1):2 with points pt 7 ps 0.4 title 'SPH particles', \\\n"
    << "  rho0g * x with lines lw 2 title 'rho0 g depth'\n";
  return {{"pressure_depth.png", s.str()}};
}

template <int D>
nlohmann::json HydrostaticCase<D>::save_state() const {
  return {{"max_drift", encode_doubles({*drift_})}};
}

template <int D>
void HydrostaticCase<D>::restore_state(const nlohmann::json& state) {
  // The monitor has already seen the restart's first evaluation: the larger of the two.
  *drift_ = std::max(*drift_, state_double(state, "max_drift"));
}

template class HydrostaticCase<2>;
template class HydrostaticCase<3>;

}  // namespace sphmol
