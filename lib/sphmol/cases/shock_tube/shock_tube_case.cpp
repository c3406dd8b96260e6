#include "sphmol/cases/shock_tube/shock_tube_case.hpp"
#include "sphmol/cases/shock_tube/shock_tube_settings.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <sstream>

#include "sphmol/run/gnuplot_preamble.hpp"
#include "sphmol/io/atomic_file.hpp"
#include "sphmol/run/timed_output_files.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/cases/shock_tube/shock_tube_scene.hpp"
#include "sphmol/run/gathered_rows.hpp"
#include "sphmol/run/piece_reduction.hpp"

namespace sphmol {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

constexpr const char* kProfileHeader =
    "x [m],rho [kg/m^3],u [m/s],p [Pa],e [J/kg],rho_exact [kg/m^3],u_exact [m/s],p_exact [Pa],e_exact [J/kg]\n";

// x where f crosses `level` between bins a and b (linear interpolation).
double crossing(const ShockTubeBin& a, const ShockTubeBin& b, double fa, double fb, double level) {
  if (fb == fa) return 0.5 * (a.x + b.x);
  return a.x + (level - fa) / (fb - fa) * (b.x - a.x);
}

}  // namespace

ShockTubeWaveKind shock_tube_wave_kind(const ExactRiemannSolver& exact, int side) {
  const double p = side == 0 ? exact.left().p : exact.right().p;
  // p* equal to the side's pressure to round-off: a wave of no strength, nothing to read.
  if (std::abs(exact.p_star() - p) <= 1e-12 * p) return ShockTubeWaveKind::none;
  return exact.p_star() > p ? ShockTubeWaveKind::shock : ShockTubeWaveKind::rarefaction;
}

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// The leftmost x within [lo, hi] where the field f passes `level` rising (rightwards) or falling.
double leftmost_crossing(const std::vector<ShockTubeBin>& bins, double ShockTubeBin::*f, double level, bool rising, double lo,
                         double hi) {
  for (std::size_t k = 0; k + 1 < bins.size(); ++k) {
    if (bins[k].x < lo) continue;
    if (bins[k + 1].x > hi) break;
    const double a = bins[k].*f, b = bins[k + 1].*f;
    if (rising ? (a < level && b >= level) : (a >= level && b < level)) return crossing(bins[k], bins[k + 1], a, b, level);
  }
  return nan;
}

// The profile seen from the other side: x -> -x, u -> -u, in ascending x.
std::vector<ShockTubeBin> mirrored(const std::vector<ShockTubeBin>& bins) {
  std::vector<ShockTubeBin> m(bins.rbegin(), bins.rend());
  for (auto& b : m) {
    b.x = -b.x;
    b.u = -b.u;
  }
  return m;
}

// The left wave of the given kind on `bins`, u_s / rho_s the left state, u* / rho*_s the star state
// beside it.
ShockTubeSideWave left_wave(const std::vector<ShockTubeBin>& bins, ShockTubeWaveKind kind, double u_s, double rho_s, double u_star,
                            double rho_star) {
  ShockTubeSideWave w{kind, nan, nan, nan};
  if (kind == ShockTubeWaveKind::rarefaction) {  // u rises from u_s to u* > u_s (Toro 2009, eq 4.56)
    w.head = leftmost_crossing(bins, &ShockTubeBin::u, u_s + 0.05 * (u_star - u_s), true, -inf, inf);
    w.tail = leftmost_crossing(bins, &ShockTubeBin::u, u_s + 0.95 * (u_star - u_s), true, -inf, inf);
  } else if (kind == ShockTubeWaveKind::shock) {  // rho rises to rho*_s, u falls to u* < u_s
    w.head = w.tail = leftmost_crossing(bins, &ShockTubeBin::rho, 0.5 * (rho_s + rho_star), true, -inf, inf);
    w.shock_velocity = leftmost_crossing(bins, &ShockTubeBin::u, 0.5 * (u_s + u_star), false, -inf, inf);
  }
  return w;
}

}  // namespace

ShockTubeWaves detect_waves(const std::vector<ShockTubeBin>& bins, const ExactRiemannSolver& exact) {
  const auto& L = exact.left();
  const auto& R = exact.right();
  const std::vector<ShockTubeBin> m = mirrored(bins);
  ShockTubeWaves w;
  w.left = left_wave(bins, shock_tube_wave_kind(exact, 0), L.u, L.rho, exact.u_star(), exact.rho_star_left());
  w.right = left_wave(m, shock_tube_wave_kind(exact, 1), -R.u, R.rho, -exact.u_star(), exact.rho_star_right());
  for (double* x : {&w.right.head, &w.right.tail, &w.right.shock_velocity}) *x = -*x;
  w.contact = nan;
  // Between the inner edges of the waves that exist (the whole tube beside a wave of no strength).
  const double lo = w.left.kind == ShockTubeWaveKind::none ? -inf : w.left.tail;
  const double hi = w.right.kind == ShockTubeWaveKind::none ? inf : w.right.tail;
  const double rl = exact.rho_star_left(), rr = exact.rho_star_right();
  if (std::isnan(lo) || std::isnan(hi) || rl == rr) return w;
  const double level = 0.5 * (rl + rr);
  // Nearest the lighter side: read from that side, on the mirrored profile when it is the right one.
  w.contact = rl < rr ? leftmost_crossing(bins, &ShockTubeBin::rho, level, true, lo, hi)
                      : -leftmost_crossing(m, &ShockTubeBin::rho, level, true, -hi, -lo);
  return w;
}

template <int D>
std::unique_ptr<SphSystem<D>> ShockTubeCase<D>::build(const Config& config) {
  auto scene = build_shock_tube_scene<D>(config);
  const auto& st = config.settings<ShockTubeSettings>();
  gamma_ = config.fluid.eos.gamma;
  exact_.emplace(EulerState{st.left.density, st.left.velocity, st.left.pressure},
                 EulerState{st.right.density, st.right.velocity, st.right.pressure}, gamma_);
  spacing_ = scene.spacing;
  length_ = config.settings<ShockTubeSettings>().tube_length;
  width_ = config.settings<ShockTubeSettings>().tube_width;
  wall_layers_ = scene.wall_layers;
  side_rows_ = scene.side_rows;
  setup_ = st.setup;
  smoothing_ = st.smoothing;
  fluid_left_ = fluid_right_ = 0;
  for (std::size_t i = 0; i < scene.particles.n_fluid; ++i) {
    if (scene.particles.x[0][i] < 0.0) {
      ++fluid_left_;
      mass_left_ = scene.particles.mass[i];
    } else {
      ++fluid_right_;
      mass_right_ = scene.particles.mass[i];
    }
  }
  profiles_ = config.output.profiles;
  const bool ghost = config.discretization.boundary == "ghost";
  boundary_ = config.discretization.boundary;
  auto sys = assemble_system<D>(config, std::move(scene.particles), scene.domain, scene.spacing, ghost ? &scene.walls : nullptr,
                                std::move(scene.energy));
  // With a constant h the kernel pass reads one h; the per-particle h0 (equal-mass spacings) needs a variable one.
  if (config.discretization.smoothing_length != "constant") sys->set_initial_smoothing_lengths(scene.h0);
  return sys;
}

template <int D>
double ShockTubeCase<D>::local_spacing(int side, double rho) const {
  const double m = side == 0 ? mass_left_ : mass_right_;
  const double dy = D == 2 ? width_ / side_rows_[static_cast<std::size_t>(side)] : 1.0;
  return m / (rho * dy);
}

template <int D>
nlohmann::json ShockTubeCase<D>::measure_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t,
                                                const OutputSink& out) {
  const SphSystem<D>& sys = *piece.system;
  const auto& L = sys.layout();
  const double* y = piece.y;
  // Fields of the state y itself (not of the last RHS stage): rho from the state when it is there.
  const double* rho = L.has_density ? y + L.density() : sys.density().data();
  const double* e = y + L.energy();
  const double x0 = -0.5 * length_;
  const int nb = static_cast<int>(std::lround(length_ / spacing_));
  // Exact sums over the ranks' own fluid (run/piece_reduction.hpp), the bins' included: the serial
  // values to the bit.
  PieceReduction r;
  const auto count = r.sum(), mid_count = r.sum(), l1 = r.sums(4), l1_mid = r.sums(4);
  // Per bin: the count, then the sums of x, rho, u, p and e.
  const auto bin_sums = r.sums(6 * static_cast<std::size_t>(nb));
  // Mid-line particles: within one spacing of y = W/2 (the two central rows); in 1D all particles.
  const bool file = profiles_ && writes_files(piece, out.enabled);
  std::vector<std::array<double, 9>> mid;
  for (const std::size_t i : piece.fluid_rows) {
    const double x = y[L.position(0) + i], u = y[L.velocity(0) + i];
    const double p = (gamma_ - 1.0) * rho[i] * e[i];
    const RiemannSample q = exact_->sample(x, t, 0.0);
    const double err[4] = {std::abs(rho[i] - q.rho), std::abs(u - q.u), std::abs(p - q.p), std::abs(e[i] - q.e)};
    const bool on_mid = D == 1 || std::abs(y[L.position(D - 1) + i] - 0.5 * width_) < spacing_;
    r.add(count, 1.0);
    for (int k = 0; k < 4; ++k) {
      r.add(l1 + k, err[k]);
      if (on_mid) r.add(l1_mid + k, err[k]);
    }
    if (on_mid) {
      r.add(mid_count, 1.0);
      if (file) mid.push_back({x, rho[i], u, p, e[i], q.rho, q.u, q.p, q.e});
    }
    const int b = static_cast<int>(std::floor((x - x0) / spacing_));
    if (b < 0 || b >= nb) continue;
    const std::size_t at = bin_sums + 6 * static_cast<std::size_t>(b);
    r.add(at, 1.0);
    r.add(at + 1, x);
    r.add(at + 2, rho[i]);
    r.add(at + 3, u);
    r.add(at + 4, p);
    r.add(at + 5, e[i]);
  }
  r.reduce(piece);
  const double n = r.value(count), n_mid = r.value(mid_count);
  std::vector<ShockTubeBin> bins;
  for (int b = 0; b < nb; ++b) {
    const std::size_t at = bin_sums + 6 * static_cast<std::size_t>(b);
    const double c = r.value(at);
    if (c == 0.0) continue;
    bins.push_back({r.value(at + 1) / c, r.value(at + 2) / c, r.value(at + 3) / c, r.value(at + 4) / c, r.value(at + 5) / c});
  }
  const ShockTubeWaves w = detect_waves(bins, *exact_);
  const RiemannWaves ex = exact_->waves(t, 0.0);
  // The same detector on the exact profile, sampled 100 times finer than the bins: the fan's edges
  // are read at 5 % / 95 % of u*, which lie inside the fan, so the SPH crossing is compared with the
  // exact crossing, not with the exact edge (for the shock and the contact the two agree).
  std::vector<ShockTubeBin> fine;
  const int n_fine = 100 * nb;
  fine.reserve(static_cast<std::size_t>(n_fine));
  for (int k = 0; k < n_fine; ++k) {
    const double x = x0 + (k + 0.5) * length_ / n_fine;
    const RiemannSample q = exact_->sample(x, t, 0.0);
    fine.push_back({x, q.rho, q.u, q.p, q.e});
  }
  const ShockTubeWaves wx = detect_waves(fine, *exact_);
  if (out.enabled && profiles_) {
    std::ostringstream s, name;
    s << kProfileHeader << std::setprecision(10);
    for (const auto& b : bins) {
      const RiemannSample q = exact_->sample(b.x, t, 0.0);
      s << b.x << ',' << b.rho << ',' << b.u << ',' << b.p << ',' << b.e << ',' << q.rho << ',' << q.u << ',' << q.p
        << ',' << q.e << '\n';
    }
    name << "profile_t" << output_time_text(t) << ".csv";
    out.write(name.str(), s.str());
  }
  // Every rank's mid-line rows on rank 0, sorted by x (then by the other columns).
  if (file) {
    mid = gather_rows(piece, mid);
    std::sort(mid.begin(), mid.end());
  }
  if (out.enabled && profiles_) {
    std::ostringstream s, name;
    s << kProfileHeader << std::setprecision(10);
    for (const auto& row : mid)
      for (int k = 0; k < 9; ++k) s << row[static_cast<std::size_t>(k)] << (k < 8 ? ',' : '\n');
    name << "midline_t" << output_time_text(t) << ".csv";
    out.write(name.str(), s.str());
  }
  const double inv_mid = n_mid > 0 ? 1.0 / n_mid : 0.0;
  auto pos = [](double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); };
  // The offset from the exact position in spacings of the denser side (discretization.spacing).
  auto offset = [this](double sph, double exact) {
    return std::isnan(sph) || std::isnan(exact) ? nlohmann::json(nullptr) : nlohmann::json((sph - exact) / spacing_);
  };
  // local: the x spacing of the gas at the wave, on its denser side (fan head: the undisturbed gas;
  // fan tail and shock: the star state of the wave's side; contact: the denser star state).
  auto wave = [&](double sph, double exact, double crossing, double local, const char* side) {
    nlohmann::json j{
        {"sph", pos(sph)}, {"exact", exact}, {"exact_crossing", pos(crossing)}, {"offset_spacings", offset(sph, crossing)},
        {"local_spacing", local}, {"side", side}};
    j["offset_local_spacings"] = std::isnan(sph) || std::isnan(crossing) ? nlohmann::json(nullptr)
                                                                         : nlohmann::json((sph - crossing) / local);
    return j;
  };
  // Each wave of the exact pattern, named by its kind; prefixed by its side when both sides have one of
  // that kind (two shocks, two fans).
  nlohmann::json waves = nlohmann::json::object();
  const bool same_kind = w.left.kind == w.right.kind;
  for (int side = 0; side < 2; ++side) {
    const ShockTubeSideWave& sw = side == 0 ? w.left : w.right;
    const ShockTubeSideWave& sx = side == 0 ? wx.left : wx.right;
    const char* name = side == 0 ? "left" : "right";
    const std::string prefix = same_kind ? std::string(name) + "_" : std::string();
    const double rho_side = side == 0 ? exact_->left().rho : exact_->right().rho;
    const double rho_star = side == 0 ? exact_->rho_star_left() : exact_->rho_star_right();
    const double head = side == 0 ? ex.left_head : ex.right_head, tail = side == 0 ? ex.left_tail : ex.right_tail;
    if (sw.kind == ShockTubeWaveKind::shock) {
      waves[prefix + "shock"] = wave(sw.head, head, sx.head, local_spacing(side, rho_star), name);
      waves[prefix + "shock_velocity"] = wave(sw.shock_velocity, head, sx.shock_velocity, local_spacing(side, rho_star), name);
    } else if (sw.kind == ShockTubeWaveKind::rarefaction) {
      waves[prefix + "rarefaction_head"] = wave(sw.head, head, sx.head, local_spacing(side, rho_side), name);
      waves[prefix + "rarefaction_tail"] = wave(sw.tail, tail, sx.tail, local_spacing(side, rho_star), name);
    }
  }
  const bool left_denser = exact_->rho_star_left() >= exact_->rho_star_right();
  waves["contact"] = wave(w.contact, ex.contact, wx.contact,
                          left_denser ? local_spacing(0, exact_->rho_star_left()) : local_spacing(1, exact_->rho_star_right()),
                          "between");
  const double inv_n = 1.0 / n;
  return {{"t", t},
          {"L1_rho", r.value(l1) * inv_n},
          {"L1_u", r.value(l1 + 1) * inv_n},
          {"L1_p", r.value(l1 + 2) * inv_n},
          {"L1_e", r.value(l1 + 3) * inv_n},
          {"L1_mid_rho", r.value(l1_mid) * inv_mid},
          {"L1_mid_u", r.value(l1_mid + 1) * inv_mid},
          {"L1_mid_p", r.value(l1_mid + 2) * inv_mid},
          {"L1_mid_e", r.value(l1_mid + 3) * inv_mid},
          {"waves", waves}};
}

template <int D>
void ShockTubeCase<D>::annotate(nlohmann::json& summary) const {
  summary["discretization"]["spacing"] = spacing_;
  summary["discretization"]["wall_layers"] = wall_layers_;
  summary["y_walls"] = D == 1 ? "none (1D)"
                       : boundary_ == "ghost"       ? "ghost (mirror) walls at y = 0 and y = W"
                       : boundary_ == "virtual_repulsive"
                           ? "virtual particles with the repulsive force (Niedoba 2012, eq 2.76) on y = -dx and y = W + dx"
                           : "none: y periodic";
  auto kind = [this](int side) {
    const ShockTubeWaveKind k = shock_tube_wave_kind(*exact_, side);
    return std::string(k == ShockTubeWaveKind::shock ? "shock" : k == ShockTubeWaveKind::rarefaction ? "rarefaction" : "none");
  };
  summary["exact"] = {{"p_star", exact_->p_star()},
                      {"u_star", exact_->u_star()},
                      {"rho_star_left", exact_->rho_star_left()},
                      {"rho_star_right", exact_->rho_star_right()},
                      {"gamma", gamma_},
                      {"wave_pattern", {{"left", kind(0)}, {"right", kind(1)}}}};
  summary["error_definitions"] = {
      {"L1", "mean over all fluid particles of |f_sph - f_exact(x_i, t)| (with y periodic every row is a mid-line; "
             "with walls the rows next to them are included)"},
      {"L1_mid", "the same mean over the mid-line particles only, |y - W/2| < dx (1D: all particles)"},
      {"waves", "the waves of the exact solution (exact.wave_pattern: a shock, a rarefaction or none on each side, and the "
                "contact), each read off the x-binned profile by a threshold crossing, the outermost on its side "
                "(side: the state it moves into); named by kind, with left_/right_ when both sides have that kind. With "
                "u_s, rho_s the side's initial state and u*, rho*_s the star state beside it: rarefaction head/tail "
                "where u passes u_s + 5%/95% of (u* - u_s), shock where rho passes (rho*_s + rho_s)/2 (the middle of the "
                "density jump), shock_velocity where u passes (u* + u_s)/2 (across a smeared shock u leads rho, so this "
                "reads ahead of the jump's middle by a fraction of the shock's width), contact where rho passes "
                "(rho*_L + rho*_R)/2. exact: the wave's exact "
                "position (fan head and tail: its edges); exact_crossing: the same threshold crossing on the exact profile; "
                "offset_spacings = (sph - exact_crossing) / discretization.spacing (the denser side's spacing); "
                "offset_local_spacings = (sph - exact_crossing) / local_spacing, the x spacing m / (rho dy) (1D: m / rho) "
                "of the gas at the wave on its denser side at the exact density there"}};
  summary["setup"] = {{"type", setup_}, {"smoothing", smoothing_}, {"fluid_left", fluid_left_}, {"fluid_right", fluid_right_},
                      {"mass_left", mass_left_}, {"mass_right", mass_right_}};
  if (profiles_) {
    summary["csv_files"]["profile_t<t>.csv"] =
        "SPH profile binned in x (bin = particle spacing, mean over the bin's particles) vs the exact Riemann solution "
        "at the bin's mean x, output time t";
    summary["csv_files"]["midline_t<t>.csv"] =
        "mid-line particles (|y - W/2| < dx; 1D: all), sorted by x, vs the exact Riemann solution at their x, output time t";
  }
}

// Rho, u, p, e on the mid-line at the last output time against the exact solution: 4 panels.
template <int D>
std::vector<PlotScript> ShockTubeCase<D>::plots(const OutputSink& out) const {
  if (!profiles_) return {};
  const auto files = timed_output_files(out, "midline_t");
  if (files.empty()) return {};
  const auto& [t_last, file] = files.back();
  std::ostringstream s;
  s << gnuplot_csv_preamble("shock tube: mid-line particles vs the exact Riemann solution (sph-mol ShockTubeCase)", 1100,
                            800, 10, "shock_tube.png")
    << "set grid\nset key center right\nset xlabel 'x [m]'\n"
    << "set multiplot layout 2,2 title \"shock tube, t = " << t_last << ": points SPH (mid-line), lines exact\"\n";
  const char* names[] = {"density rho", "velocity u", "pressure p", "internal energy e"};
  for (int k = 0; k < 4; ++k)
    s << "set title '" << names[k] << "'\nplot '" << file << "' using 1:" << k + 2
      << " with points pt 7 ps 0.4 title 'SPH', '' using 1:" << k + 6 << " with lines lw 1.5 title 'exact'\n";
  s << "unset multiplot\n";
  return {{"shock_tube.png", s.str()}};
}

template class ShockTubeCase<1>;
template class ShockTubeCase<2>;

}  // namespace sphmol
