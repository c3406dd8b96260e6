#include "sphmol/cases/cavity/cavity_case.hpp"
#include "sphmol/cases/cavity/cavity_settings.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "sphmol/run/case_state.hpp"
#include "sphmol/run/gnuplot_preamble.hpp"
#include "sphmol/run/piece_reduction.hpp"
#include "sphmol/io/atomic_file.hpp"
#include "sphmol/kernels/registry.hpp"
#include "sphmol/reference/data_directory.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/scenes/box_scene.hpp"
#include "sphmol/run/timed_output_files.hpp"

namespace sphmol {

std::unique_ptr<SphSystem<2>> CavityCase::build(const Config& config) {
  L_ = config.settings<CavitySettings>().box[0];
  if (std::abs(config.settings<CavitySettings>().box[1] - L_) > 1e-12 * L_)
    throw std::invalid_argument("geometry.box: the Ghia reference is for a square cavity");
  if (config.discretization.boundary == "virtual_repulsive")
    throw std::invalid_argument("discretization.boundary: virtual_repulsive walls exert no shear, so the lid cannot drive the cavity");
  if (config.fluid.kinematic_viscosity <= 0) throw std::invalid_argument("fluid.kinematic_viscosity: cavity needs nu > 0");
  U_ = config.settings<CavitySettings>().wall_velocity;
  Re_ = std::abs(U_) * L_ / config.fluid.kinematic_viscosity;
  ghia_ = load_ghia(reference_data_file("ghia1982_u_vertical_centreline.csv"),
                    reference_data_file("ghia1982_v_horizontal_centreline.csv"), Re_);
  kernel_ = config.discretization.kernel;
  profiles_ = config.output.profiles;
  BoxWalls<2> walls{};
  for (int d = 0; d < 2; ++d) walls[d][0].present = walls[d][1].present = true;
  walls[1][1].velocity = {U_, 0.0};
  BoxScene s = build_box_scene(config, L_, L_, L_, walls, false);
  spacing_ = s.spacing;
  return assemble_system<2>(config, std::move(s.particles), s.domain, s.spacing, &s.walls);
}

std::string CavityCase::reference() const {
  return ghia_ ? "Ghia, Ghia & Shin (1982), Re = " + std::to_string(Re_) : "none: no Ghia table for Re = " + std::to_string(Re_);
}

nlohmann::json CavityCase::measure_pieces(const SphSystem<2>& whole, const OwnedPiece<2>& piece, double t,
                                          const OutputSink& out) {
  const SphSystem<2>& sys = *piece.system;
  const auto& lay = sys.layout();
  const double* y = piece.y;
  const auto& m = sys.particles().mass;
  const auto& rho = sys.density();
  const double h = whole.smoothing_length();
  const auto K = kernel_info<2>(kernel_);
  // Every sum of the measurement (the kinetic energy, the moving least-squares systems of the table
  // points below) exactly over the ranks' own fluid (run/piece_reduction.hpp), in one reduction:
  // the serial values to the bit.
  PieceReduction r;
  const auto ke_sum = r.sum();
  // Velocity component c at (px, py) by linear moving least squares (Lancaster & Salkauskas 1981; in
  // SPH, Dilts 1999): u ~ a + b . (x - p) fitted with weights V_i W(|x_i - p|), and a is the value.
  // It is exact for a linear field, also where the support is cut by a wall. The Shepard average
  // (a alone, zeroth order) is biased there by about h du/dy: at the table point 0.6 spacings below
  // the lid (y = 0.9766 L, 40 across, h = 2 dx) it read 0.785 U against Ghia's 0.841 U, and the three
  // table points within one h of the lid made up 96 % of u_rms^2 (Re 100, t = 20 s). Falls back to
  // Shepard where the fit is singular (too few neighbours).
  struct Fit {
    double px, py;
    int c;
    PieceReduction::Slot A, b;  // the 9 sums of A (row by row), then the 3 of b
  };
  // A lid moving along -x drives the mirror image (x -> L - x) of the flow Ghia et al. tabulate for a
  // lid along +x: the run is measured in their frame, where u' = -u and v' = v. So u/U is compared as
  // it is, and v at table point x is the run's v at L - x, over |U|.
  const bool mirrored = U_ < 0.0;
  std::vector<Fit> fits;
  if (ghia_) {
    for (const double yy : ghia_->y)
      if (yy > 0.0 && yy < 1.0) fits.push_back({0.5 * L_, yy * L_, 0, r.sums(9), r.sums(3)});
    for (const double xx : ghia_->x)
      if (xx > 0.0 && xx < 1.0) fits.push_back({(mirrored ? 1.0 - xx : xx) * L_, 0.5 * L_, 1, r.sums(9), r.sums(3)});
  }
  for (const std::size_t i : piece.fluid_rows) {
    r.add(ke_sum, 0.5 * m[i] * (std::pow(y[lay.velocity(0) + i], 2) + std::pow(y[lay.velocity(1) + i], 2)));
    for (const Fit& f : fits) {
      const double ex = y[lay.position(0) + i] - f.px, ey = y[lay.position(1) + i] - f.py;
      const double w = K.W(std::hypot(ex, ey), h) * m[i] / rho[i];
      if (w == 0.0) continue;
      const double q[3] = {1.0, ex, ey};
      for (int a = 0; a < 3; ++a) {
        r.add(f.b + a, w * q[a] * y[lay.velocity(f.c) + i]);
        for (int e = 0; e < 3; ++e) r.add(f.A + 3 * a + e, w * q[a] * q[e]);
      }
    }
  }
  r.reduce(piece);
  const double ke = r.value(ke_sum);
  const double dke = ke_prev_ > 0.0 ? std::abs(ke - ke_prev_) / ke : 1.0;
  // Changes per convective time L/U, so the criterion does not depend on how far apart outputs are.
  const double conv = t > t_prev_ ? (t - t_prev_) * std::abs(U_) / L_ : 0.0;
  const double ke_rate = ke_prev_ > 0.0 && conv > 0.0 ? dke / conv : 1.0;
  ke_prev_ = ke;
  nlohmann::json result = {{"t", t}, {"kinetic_energy", ke}, {"rel_ke_change", dke}, {"ke_rate", ke_rate}};
  if (!ghia_) {
    t_prev_ = t;
    return result;
  }
  // The fitted value at a table point from its reduced sums.
  auto interpolate = [&](const Fit& f) {
    double A[3][3], b[3];
    for (int a = 0; a < 3; ++a) {
      b[a] = r.value(f.b + a);
      for (int e = 0; e < 3; ++e) A[a][e] = r.value(f.A + 3 * a + e);
    }
    if (A[0][0] <= 0.0) return 0.0;
    // Cramer's rule for the first unknown, on the system scaled by h so the entries are O(1).
    const double s = 1.0 / h;
    const double M[3][3] = {{A[0][0], A[0][1] * s, A[0][2] * s},
                            {A[1][0] * s, A[1][1] * s * s, A[1][2] * s * s},
                            {A[2][0] * s, A[2][1] * s * s, A[2][2] * s * s}};
    const double rhs[3] = {b[0], b[1] * s, b[2] * s};
    const auto det3 = [](const double (&X)[3][3]) {
      return X[0][0] * (X[1][1] * X[2][2] - X[1][2] * X[2][1]) - X[0][1] * (X[1][0] * X[2][2] - X[1][2] * X[2][0]) +
             X[0][2] * (X[1][0] * X[2][1] - X[1][1] * X[2][0]);
    };
    const double det = det3(M);
    if (!(std::abs(det) > 1e-10 * std::pow(A[0][0], 3))) return b[0] / A[0][0];
    double M0[3][3];
    for (int a = 0; a < 3; ++a) {
      M0[a][0] = rhs[a];
      M0[a][1] = M[a][1];
      M0[a][2] = M[a][2];
    }
    return det3(M0) / det;
  };
  // One file per centre line, so that every column is numeric.
  std::ostringstream csv_u, csv_v;
  csv_u << std::setprecision(10) << "y/L [-],u_sph/U [-],u_ghia/U [-]\n";
  csv_v << std::setprecision(10) << "x/L [-],v_sph/U [-],v_ghia/U [-]\n";
  double su = 0, mu = 0, sv = 0, mv = 0;
  int nu = 0, nv = 0;
  std::vector<double> line;  // SPH values at the table points, u then v (steadiness)
  std::size_t next_fit = 0;  // the table points in the order of `fits`
  for (std::size_t k = 0; k < ghia_->y.size(); ++k) {
    const double yy = ghia_->y[k];
    if (yy <= 0.0 || yy >= 1.0) continue;
    const double u = interpolate(fits.at(next_fit++)) / U_;
    line.push_back(u);
    const double e = u - ghia_->u[k];
    su += e * e;
    mu = std::max(mu, std::abs(e));
    ++nu;
    csv_u << yy << ',' << u << ',' << ghia_->u[k] << '\n';
  }
  for (std::size_t k = 0; k < ghia_->x.size(); ++k) {
    const double xx = ghia_->x[k];
    if (xx <= 0.0 || xx >= 1.0) continue;
    const double v = interpolate(fits.at(next_fit++)) / std::abs(U_);
    line.push_back(v);
    const double e = v - ghia_->v[k];
    sv += e * e;
    mv = std::max(mv, std::abs(e));
    ++nv;
    csv_v << xx << ',' << v << ',' << ghia_->v[k] << '\n';
  }
  if (out.enabled && profiles_) {
    std::ostringstream tag;
    tag << "_t" << output_time_text(t) << ".csv";
    last_u_csv_ = "centreline_u" + tag.str();
    last_v_csv_ = "centreline_v" + tag.str();
    out.write(last_u_csv_, csv_u.str());
    out.write(last_v_csv_, csv_v.str());
    last_t_ = t;
  }
  double change = 1.0;
  if (line_prev_.size() == line.size() && conv > 0.0) {
    double s2 = 0.0;
    for (std::size_t k = 0; k < line.size(); ++k) s2 += (line[k] - line_prev_[k]) * (line[k] - line_prev_[k]);
    change = std::sqrt(s2 / static_cast<double>(line.size())) / conv;
  }
  line_prev_ = std::move(line);
  t_prev_ = t;
  result["centreline_rate"] = change;
  result["u_rms"] = std::sqrt(su / nu);
  result["u_max"] = mu;
  result["v_rms"] = std::sqrt(sv / nv);
  result["v_max"] = mv;
  return result;
}

nlohmann::json CavityCase::final_errors(const nlohmann::json& errors) const {
  nlohmann::json f = Case<2>::final_errors(errors);
  if (!f.empty()) {
    bool steady = f["ke_rate"].get<double>() < kSteadyRate;
    if (f.contains("centreline_rate")) steady = steady && f["centreline_rate"].get<double>() < kSteadyRate;
    f["steady"] = steady;
  }
  return f;
}

nlohmann::json CavityCase::save_state() const {
  return {{"ke_prev", encode_doubles({ke_prev_})}, {"t_prev", encode_doubles({t_prev_})}, {"line_prev", encode_doubles(line_prev_)}};
}

void CavityCase::restore_state(const nlohmann::json& state) {
  ke_prev_ = state_double(state, "ke_prev");
  t_prev_ = state_double(state, "t_prev");
  line_prev_ = state_doubles(state, "line_prev");
}

void CavityCase::annotate(nlohmann::json& summary) const {
  summary["Re"] = Re_;
  summary["lid_velocity"] = U_;
  summary["compared"] = ghia_.has_value();
  summary["interpolation"] = "linear moving least squares (kernel-weighted, fluid particles)";
  summary["steadiness"] =
      "per convective time L/U between the last two outputs: relative kinetic-energy change (ke_rate) and RMS "
      "change of the centre-line velocities / U (centreline_rate); steady if both < 5e-3";
  summary["discretization"]["spacing"] = spacing_;
  if (ghia_ && profiles_) {
    std::ostringstream r;
    r << " vs Ghia, Ghia & Shin (1982) Tables I and II at Re = " << Re_
      << "; SPH velocities interpolated to the table points by linear moving least squares, output time t";
    const std::string ref = r.str();
    // A lid along -x: the run mirrored in x, in the tables' frame (measure_pieces).
    const std::string frame = U_ < 0.0 ? "; lid speed < 0: in the frame mirrored in x (x -> L - x, u -> -u, U -> |U|), "
                                         "where the lid moves along +x as in the tables"
                                       : "";
    summary["csv_files"]["centreline_u_t<t>.csv"] = "u/U on the vertical centre line x = L/2" + ref + frame;
    summary["csv_files"]["centreline_v_t<t>.csv"] = "v/U on the horizontal centre line y = L/2" + ref + frame;
  }
}

std::vector<PlotScript> CavityCase::plots(const OutputSink& out) const {
  if (!ghia_ || last_u_csv_.empty()) return {};
  std::ostringstream s;
  s << gnuplot_csv_preamble("Cavity centre lines vs Ghia, Ghia & Shin (1982) (sph-mol CavityCase)", 1200, 560, 11,
                            "centrelines.png")
    << "set multiplot layout 1,2 title \"Lid-driven cavity, Re = " << Re_ << ", t = " << last_t_
    << " s: lines SPH, points Ghia et al. (1982)\" noenhanced\n"
    << "set grid\nset key bottom right\n"
    << "set xlabel 'u / U at x = 0.5'\nset ylabel 'y / L'\nset yrange [0:1]\n"
    << "plot '" << last_u_csv_ << "' using 2:1 with linespoints pt 6 lw 2 title 'SPH', \\\n"
    << "  '" << last_u_csv_ << "' using 3:1 with points pt 7 ps 1.3 title 'Ghia'\n"
    << "set xlabel 'x / L'\nset ylabel 'v / U at y = 0.5'\nset xrange [0:1]\nset autoscale y\nset key top right\n"
    << "plot '" << last_v_csv_ << "' using 1:2 with linespoints pt 6 lw 2 title 'SPH', \\\n"
    << "  '" << last_v_csv_ << "' using 1:3 with points pt 7 ps 1.3 title 'Ghia'\n"
    << "unset multiplot\n";
  return {{"centrelines.png", s.str()}};
}

}  // namespace sphmol
