#include "sphmol/cases/hydrostatic/hydrostatic_case.hpp"
#include "sphmol/cases/hydrostatic/hydrostatic_settings.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "sphmol/run/gnuplot_preamble.hpp"
#include "sphmol/analysis/drift_monitor.hpp"
#include "sphmol/io/atomic_file.hpp"
#include "sphmol/run/timed_output_files.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/scenes/box_scene.hpp"

namespace sphmol {

std::unique_ptr<SphSystem<2>> HydrostaticCase::build(const Config& config) {
  const double width = config.settings<HydrostaticSettings>().box[0];
  depth_ = config.settings<HydrostaticSettings>().box[1];
  rho0_ = config.fluid.density;
  g_ = -config.fluid.body_force[1];
  if (g_ <= 0.0 || config.fluid.body_force[0] != 0.0)
    throw std::invalid_argument("fluid.body_force: hydrostatic needs gravity [0, -g] with g > 0");
  settle_ = 2.0 * config.fluid.body_force_ramp;
  BoxWalls<2> walls{};
  walls[0][0].present = walls[0][1].present = walls[1][0].present = true;  // open top: free surface
  const double dx0 = config.discretization.particles_across > 0 ? width / config.discretization.particles_across
                                                                : config.discretization.spacing;
  const double tank = std::round(1.2 * depth_ / dx0) * dx0;
  BoxScene s = build_box_scene(config, width, tank, depth_, walls, false);
  spacing_ = s.spacing;
  Particles<2> initial = s.particles;
  auto sys = assemble_system<2>(config, std::move(s.particles), s.domain, s.spacing, &s.walls);
  sys->append_term(std::make_unique<DriftMonitor<2>>(initial, drift_));
  return sys;
}

nlohmann::json HydrostaticCase::measure(const SphSystem<2>& sys, const double* y, double t, const OutputSink& out) {
  const auto& lay = sys.layout();
  const std::size_t n = lay.n;
  const auto& p = sys.pressure();
  const double scale = rho0_ * g_ * depth_;
  double s2 = 0.0, emax = 0.0;
  std::ostringstream csv;
  csv << "y [m],p_sph [Pa],p_exact [Pa]\n" << std::setprecision(10);
  for (std::size_t i = 0; i < n; ++i) {
    const double yi = y[lay.position(1) + i];
    const double pe = rho0_ * g_ * (depth_ - yi);
    const double e = (p[i] - pe) / scale;
    s2 += e * e;
    emax = std::max(emax, std::abs(e));
    csv << yi << ',' << p[i] << ',' << pe << '\n';
  }
  if (out.enabled) {
    std::ostringstream name;
    name << "pressure_t" << std::setprecision(6) << t << ".csv";
    out.write(name.str(), csv.str());
  }
  return {{"t", t}, {"settled", t >= settle_}, {"p_rms", std::sqrt(s2 / static_cast<double>(n))}, {"p_max", emax},
          {"max_drift", *drift_ / spacing_}};
}

// Worst over the settled output times: the errors must stay bounded, not only end small.
nlohmann::json HydrostaticCase::final_errors(const nlohmann::json& errors) const {
  double prms = 0.0, pmax = 0.0;
  int settled = 0;
  for (const auto& e : errors)
    if (e["settled"].get<bool>()) {
      prms = std::max(prms, e["p_rms"].get<double>());
      pmax = std::max(pmax, e["p_max"].get<double>());
      ++settled;
    }
  nlohmann::json f = {{"max_drift", *drift_ / spacing_}, {"settled_outputs", settled}};
  if (settled > 0) {
    f["p_rms"] = prms;
    f["p_max"] = pmax;
  } else {
    f["p_rms"] = nullptr;
    f["p_max"] = nullptr;
  }
  return f;
}

void HydrostaticCase::annotate(nlohmann::json& summary) const {
  summary["settle_time"] = settle_;
  summary["final_errors_note"] = "p_rms, p_max: worst over output times t >= settle_time; max_drift over all RHS evaluations";
  summary["discretization"]["spacing"] = spacing_;
  summary["csv_files"]["pressure_t<t>.csv"] =
      "pressure of every fluid particle vs the hydrostatic p = rho0 g (depth - y) at output time t";
}

// p against depth at the last output time: every fluid particle, and the line rho0 g depth.
std::vector<PlotScript> HydrostaticCase::plots(const OutputSink& out) const {
  const auto files = timed_output_files(out, "pressure_t");
  if (files.empty()) return {};
  const auto& [t_last, file] = files.back();
  std::ostringstream s;
  s << std::setprecision(10)
    << gnuplot_csv_preamble("hydrostatic column: p vs depth (sph-mol HydrostaticCase)", 800, 640, 11, "pressure_depth.png")
    << "set title \"hydrostatic pressure at t = " << t_last << " s\"\n"
    << "set xlabel 'depth H - y [m]'\nset ylabel 'p [Pa]'\nset key top left\nset grid\n"
    << "H = " << depth_ << "\nrho0g = " << rho0_ * g_ << "\nset xrange [0:H]\n"
    << "plot '" << file << "' using (H - $1):2 with points pt 7 ps 0.4 title 'SPH particles', \\\n"
    << "  rho0g * x with lines lw 2 title 'rho0 g depth'\n";
  return {{"pressure_depth.png", s.str()}};
}

}  // namespace sphmol
