#include "sphmol/cases/channel/channel_case.hpp"
#include "sphmol/cases/channel/channel_settings.hpp"

#include <algorithm>
#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sphmol/run/gnuplot_preamble.hpp"
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

nlohmann::json ChannelCase::measure(const SphSystem<2>& sys, const double* y, double t, const OutputSink& out) {
  // A fluid particle pushed into the wall layers (the health check allows them: they are inside the
  // domain) has no reference value: that run has blown up (stability studies near the step limit).
  // Tested here by position, so that any other error of the reference stays an error.
  const auto& L = sys.layout();
  for (std::size_t i = 0; i < L.n; ++i) {
    const double yi = y[L.position(1) + i];
    if (!(yi >= 0.0 && yi <= height_))
      throw BlowUp(t, static_cast<long>(i), "fluid particle inside a wall (y = " + std::to_string(yi) + " m, channel [0, " +
                                                std::to_string(height_) + "] m)");
  }
  const ChannelErrors e = channel_errors(sys, y, t, ref_);
  if (out.enabled && profiles_) {
    std::ostringstream s, name;
    s << "y [m],u_sph [m/s],u_exact [m/s]\n" << std::setprecision(12);
    for (const auto& p : e.profile) s << p.y << ',' << p.u_sph << ',' << p.u_exact << '\n';
    name << "profile_t" << std::setprecision(6) << t << ".csv";
    out.write(name.str(), s.str());
  }
  // Signed mean profile error / v0: its sign changes over time reveal the oscillation about the
  // reference (Vukčević 2012, §9, Vukčević et al. 2012, §5) that the stability study classifies.
  double signed_sum = 0.0;
  for (const auto& p : e.profile) signed_sum += p.u_sph - p.u_exact;
  const double e_signed = e.profile.empty() ? 0.0 : signed_sum / (static_cast<double>(e.profile.size()) * ref_.v0);
  return {{"t", t}, {"e_rms", e.e_rms}, {"e_max", e.e_max}, {"e_signed", e_signed}};
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
