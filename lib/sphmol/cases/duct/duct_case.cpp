#include "sphmol/cases/duct/duct_case.hpp"
#include "sphmol/cases/duct/duct_settings.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "sphmol/geometry/lattice.hpp"
#include "sphmol/geometry/wall_layers.hpp"
#include "sphmol/reference/ramped_start.hpp"
#include "sphmol/kernels/registry.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/run/case_state.hpp"
#include "sphmol/run/gnuplot_preamble.hpp"
#include "sphmol/run/timed_output_files.hpp"
#include "sphmol/scenes/lattice_mass.hpp"
#include "sphmol/run/gathered_rows.hpp"
#include "sphmol/run/piece_reduction.hpp"

namespace sphmol {

namespace {

// A whole number of spacings in `length`, or an error naming `key`.
int whole(double length, double dx, const std::string& key) {
  const long n = std::lround(length / dx);
  if (n <= 0 || std::abs(n * dx - length) > 1e-6 * length)
    throw std::invalid_argument(key + ": must be a whole number of particle spacings (" + std::to_string(dx) + " m)");
  return static_cast<int>(n);
}

}  // namespace

double DuctCase::exact(double y, double z, double t) const {
  // The series' own accuracy is about 1e-13 of g c^2 / nu (reference/duct_series.hpp).
  const double tol = 1e-9 * std::abs(ref_.centre_velocity());
  return ramped_start([&](double tau) { return ref_.velocity(y, z, tau); }, t, ramp_, tol);
}

std::unique_ptr<SphSystem<3>> DuctCase::build(const Config& config) {
  const auto& s = config.settings<DuctSettings>();
  const auto& disc = config.discretization;
  const double a = s.half_width_y, b = s.half_width_z;
  ref_ = DuctSeries{a, b, config.fluid.kinematic_viscosity, config.fluid.body_force.empty() ? 0.0 : config.fluid.body_force[0]};
  ramp_ = config.fluid.body_force_ramp;
  length_ = s.length;
  profiles_ = config.output.profiles;
  // particles_across counts fluid particles across the y width 2a.
  const double dx = disc.particles_across > 0 ? 2.0 * a / disc.particles_across : disc.spacing;
  whole(2.0 * a, dx, "geometry.half_widths");
  whole(2.0 * b, dx, "geometry.half_widths");
  whole(length_, dx, "geometry.length");
  spacing_ = dx;
  const double h = disc.smoothing_ratio * dx;
  const double support = kernel_info<3>(disc.kernel).support * h;
  const int layers = disc.wall_layers > 0 ? disc.wall_layers : static_cast<int>(std::ceil(support / dx));

  const geometry::Vec<3> lo{0.0, -a, -b}, hi{length_, a, b};
  geometry::Lattice<3> lattice;
  lattice.spacing = dx;
  lattice.origin = lo;
  const double rho0 = config.fluid.density;
  const double m = lattice_mass<3>(disc.particle_mass, disc.kernel, rho0, dx, h);
  Particles<3> P;
  lattice.for_each_in(geometry::Bounds<3>{lo, hi}, [&](const geometry::Vec<3>& p) {
    P.add(Kind::Fluid, {p[0], p[1], p[2]}, {0.0, 0.0, 0.0}, m, rho0);
  });
  // The x faces are open: the duct continues periodically there.
  const auto walls = geometry::box_container_walls<3>(lo, hi, {true, true, false, false, false, false}, lattice, layers * dx);
  for (const auto& w : walls)
    P.add(Kind::Wall, {w.x[0], w.x[1], w.x[2]}, {0.0, 0.0, 0.0}, m, rho0, {w.normal[0], w.normal[1], w.normal[2]}, w.depth);
  Domain<3> domain;
  domain.lo = {0.0, -a - layers * dx, -b - layers * dx};
  domain.hi = {length_, a + layers * dx, b + layers * dx};
  domain.periodic = {true, false, false};
  return assemble_system<3>(config, std::move(P), domain, dx);
}

double DuctCase::velocity_scale(const Config& config) const {
  const auto& s = config.settings<DuctSettings>();
  const double g = config.fluid.body_force.empty() ? 0.0 : config.fluid.body_force[0];
  return std::abs(DuctSeries{s.half_width_y, s.half_width_z, config.fluid.kinematic_viscosity, g}.centre_velocity());
}

nlohmann::json DuctCase::measure_pieces(const SphSystem<3>& whole, const OwnedPiece<3>& piece, double t,
                                        const OutputSink& out) {
  const auto& lay = piece.system->layout();
  const double* y = piece.y;
  // Errors relative to the speed |u_max| and the peak along the flow, whose direction is the sign of
  // g: a flow driven along -x scores as its mirror image along +x.
  const double umax = std::abs(ref_.centre_velocity());
  const double along = ref_.g < 0.0 ? -1.0 : 1.0;
  // Exact sums and maxima over the ranks' own fluid (run/piece_reduction.hpp): the serial values to the bit.
  PieceReduction r;
  const auto count = r.sum(), squares = r.sum(), largest = r.largest(), crossing = r.largest(), fastest = r.largest(),
             fastest_exact = r.largest();
  for (const std::size_t i : piece.fluid_rows) {
    // A particle pushed onto or past a wall (it should not be) is measured at the wall.
    const double py = std::clamp(y[lay.position(1) + i], -ref_.a, ref_.a);
    const double pz = std::clamp(y[lay.position(2) + i], -ref_.b, ref_.b);
    const double u = y[lay.velocity(0) + i];
    const double ue = exact(py, pz, t);
    const double e = std::abs(u - ue);
    r.add(count, 1.0);
    r.add(squares, e * e);
    r.add(largest, e);
    r.add(crossing, std::hypot(y[lay.velocity(1) + i], y[lay.velocity(2) + i]));
    r.add(fastest, along * u);
    r.add(fastest_exact, along * ue);
  }
  r.reduce(piece);
  // The largest values from 0; the peaks as u_x, with the flow's sign.
  const double n = r.value(count), sum2 = r.value(squares), emax = std::max(0.0, r.value(largest));
  const double cross = std::max(0.0, r.value(crossing)), peak = along * std::max(0.0, r.value(fastest));
  const double peak_exact = along * std::max(0.0, r.value(fastest_exact));
  t_.push_back(t);
  peak_sph_.push_back(peak);
  peak_exact_.push_back(peak_exact);
  if (out.enabled) {
    std::ostringstream s;
    s << "t [s],u_peak_sph [m/s],u_peak_exact [m/s]\n" << std::setprecision(12);
    for (std::size_t k = 0; k < t_.size(); ++k) s << t_[k] << ',' << peak_sph_[k] << ',' << peak_exact_[k] << '\n';
    out.write("peak.csv", s.str());
  }
  // The profile's rows beside the mid-plane: |z| below one spacing; every rank's on rank 0, sorted.
  std::vector<std::array<double, 3>> rows;
  if (profiles_ && writes_files(piece, out.enabled)) {
    for (const std::size_t i : piece.fluid_rows) {
      const double pz = y[lay.position(2) + i];
      if (std::abs(pz) >= spacing_) continue;
      const double py = std::clamp(y[lay.position(1) + i], -ref_.a, ref_.a);
      rows.push_back({py, y[lay.velocity(0) + i], exact(py, std::clamp(pz, -ref_.b, ref_.b), t)});
    }
    rows = gather_rows(piece, rows);
    std::sort(rows.begin(), rows.end());
  }
  if (out.enabled && profiles_) {
    std::ostringstream s, name;
    s << "y [m],u_sph [m/s],u_exact [m/s]\n" << std::setprecision(12);
    for (const auto& row : rows) s << row[0] << ',' << row[1] << ',' << row[2] << '\n';
    name << "profile_t" << output_time_text(t) << ".csv";
    out.write(name.str(), s.str());
  }
  const double rms = n > 0 ? std::sqrt(sum2 / n) : 0.0;
  return {{"t", t}, {"e_rms", rms / umax}, {"e_max", emax / umax}, {"e_cross", cross / umax}};
}

nlohmann::json DuctCase::save_state() const {
  return {{"t", encode_doubles(t_)}, {"u_peak_sph", encode_doubles(peak_sph_)}, {"u_peak_exact", encode_doubles(peak_exact_)}};
}

void DuctCase::restore_state(const nlohmann::json& state) {
  restore_columns(state, {{"t", &t_}, {"u_peak_sph", &peak_sph_}, {"u_peak_exact", &peak_exact_}});
}

void DuctCase::annotate(nlohmann::json& summary) const {
  const double umean = ref_.mean_velocity();
  summary["duct"] = {{"half_width_y", ref_.a},
                     {"half_width_z", ref_.b},
                     {"length", length_},
                     {"body_force", ref_.g},
                     {"u_max", ref_.centre_velocity()},
                     {"u_mean", umean},
                     // Hydraulic diameter 4 A / perimeter = 4 a b / (a + b).
                     {"Re_hydraulic", umean * 4.0 * ref_.a * ref_.b / (ref_.a + ref_.b) / ref_.nu},
                     {"viscous_time", std::min(ref_.a, ref_.b) * std::min(ref_.a, ref_.b) / ref_.nu}};
  summary["discretization"]["spacing"] = spacing_;
  summary["csv_files"]["peak.csv"] =
      "u_x of the fastest particle along the flow (the sign of g) and of the fastest exact start-up speed at the "
      "particles, at every output time";
  if (profiles_)
    summary["csv_files"]["profile_t<t>.csv"] =
        "u_x across the duct (fluid particles of the two rows beside the mid-plane z = 0) vs the series, at output time t";
}

std::vector<PlotScript> DuctCase::plots(const OutputSink& out) const {
  std::vector<PlotScript> scripts;
  if (!t_.empty()) {
    std::ostringstream s;
    s << gnuplot_csv_preamble("Square duct: peak speed vs the start-up series (sph-mol DuctCase)", 900, 640, 11, "peak.png")
      << "set title \"Rectangular duct start-up: largest u_x (points SPH, line series)\" noenhanced\n"
      << "set xlabel 't [s]'\nset ylabel 'u_x [m/s]'\nset grid\nset key bottom right\n"
      << "plot 'peak.csv' using 1:3 with lines lw 2 title 'series', \\\n"
      << "  'peak.csv' using 1:2 with points pt 7 ps 1.2 title 'SPH'\n";
    scripts.push_back({"peak.png", s.str()});
  }
  const auto files = profiles_ ? timed_output_files(out, "profile_t") : std::vector<std::pair<double, std::string>>{};
  if (!files.empty()) {
    std::ostringstream s;
    s << gnuplot_csv_preamble("Square duct: u across the mid-plane vs the series (sph-mol DuctCase)", 900, 640, 11, "profiles.png")
      << "set title \"Rectangular duct: u_x(y) beside z = 0 at the output times; points SPH, lines series\" noenhanced\n"
      << "set xlabel 'y [m]'\nset ylabel 'u_x [m/s]'\nset key outside right top\nset grid\n"
      << "plot \\\n";
    for (std::size_t i = 0; i < files.size(); ++i) {
      const auto& [tt, f] = files[i];
      s << "  '" << f << "' using 1:2 with points pt 7 ps 0.6 lc " << i + 1 << " title 't = " << tt << " s', \\\n"
        << "  '" << f << "' using 1:3 with lines lw 1.5 lc " << i + 1 << " notitle" << (i + 1 < files.size() ? ", \\\n" : "\n");
    }
    scripts.push_back({"profiles.png", s.str()});
  }
  return scripts;
}

}  // namespace sphmol
