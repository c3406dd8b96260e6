#include "sphmol/cases/dam_break/dam_break_case.hpp"
#include "sphmol/cases/dam_break/dam_break_settings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "sphmol/run/case_state.hpp"
#include "sphmol/run/gnuplot_preamble.hpp"
#include "sphmol/run/piece_reduction.hpp"
#include "sphmol/time/fixed_point_norm.hpp"
#include "sphmol/io/atomic_file.hpp"
#include "sphmol/reference/dam_break_front.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/cases/dam_break/dam_break_scene.hpp"

namespace sphmol {

std::unique_ptr<SphSystem<2>> DamBreakCase::build(const Config& config) {
  DamBreakScene s = build_dam_break_scene(config);
  a_ = config.settings<DamBreakSettings>().column[0];
  H_ = config.settings<DamBreakSettings>().column[1];
  Lx_ = config.settings<DamBreakSettings>().box[0];
  t_end_ = config.time.t_end;
  g_ = s.g;
  experiments_ = experiments_apply(a_, H_);
  dx_ = s.spacing;
  wall_layers_ = s.wall_layers;
  n_fluid0_ = s.particles.n_fluid;
  n_wall_ = s.particles.n_wall();
  // The exact sum the measurement takes (run/piece_reduction.hpp): mass_change is 0 while no mass is lost.
  mass0_ = fixed_point_total(s.particles.mass.data(), n_fluid0_);
  csv_ = "t [s],T [-],x_front [m],x_ritter [m],x_mm [m],x_ko [m]\n";
  auto sys = assemble_system<2>(config, std::move(s.particles), s.domain, s.spacing);
  sys->add_monitor(std::make_shared<WallPenetrationMonitor>(Lx_, config.settings<DamBreakSettings>().box[1], penetration_));
  return sys;
}

nlohmann::json DamBreakCase::measure_pieces(const SphSystem<2>& whole, const OwnedPiece<2>& piece, double t,
                                            const OutputSink& out) {
  const SphSystem<2>& sys = *piece.system;
  const auto& L = sys.layout();
  const auto& m = sys.particles().mass;
  const double* y = piece.y;
  // The front (a largest position) and the mass exactly over the ranks (run/piece_reduction.hpp).
  PieceReduction r;
  const auto front = r.largest(), mass_sum = r.sum();
  for (const std::size_t i : piece.fluid_rows) {
    // The front of the fluid in the run; fluid that left the domain (run/outflow.hpp) keeps its mass.
    if (!sys.is_retired(i)) r.add(front, y[L.position(0) + i]);
    if (std::isfinite(y[L.position(0) + i]) && std::isfinite(y[L.position(1) + i])) r.add(mass_sum, m[i]);
  }
  r.reduce(piece);
  const double xmax = r.value(front), mass = r.value(mass_sum);
  const double x_front = xmax + 0.5 * dx_;
  const double x_ritter = ritter_front(a_, g_, H_, t);
  const double T = t * std::sqrt(2.0 * g_ / a_);
  // Empty for a column that is not the experiments' (no data span: nothing to interpolate).
  const std::span<const FrontPoint> none{};
  const auto mm = interpolate_front(experiments_ ? martin_moyce_1952_n2_2() : none, T);
  const auto ko = interpolate_front(experiments_ ? koshizuka_oka_1996() : none, T);
  const bool impacted = x_front >= Lx_ - dx_;
  nlohmann::json j = {{"t", t},
                      {"x_front", x_front},
                      {"x_ritter", x_ritter},
                      {"impacted", impacted},
                      {"mass_change", (mass - mass0_) / mass0_},
                      {"wall_penetrations", penetration_->count}};
  j["x_mm"] = mm ? nlohmann::json(*mm * a_) : nlohmann::json(nullptr);
  j["x_ko"] = ko ? nlohmann::json(*ko * a_) : nlohmann::json(nullptr);

  std::ostringstream row;
  row << std::setprecision(10) << t << ',' << T << ',' << x_front << ',' << x_ritter << ',';
  // Outside the experiments' time range, or for a column that is not theirs: an empty cell (missing
  // to pandas, numpy and gnuplot).
  if (mm) row << *mm * a_;
  row << ',';
  if (ko) row << *ko * a_;
  row << '\n';
  csv_ += row.str();
  if (out.enabled) out.write("front.csv", csv_);
  return j;
}

nlohmann::json DamBreakCase::final_errors(const nlohmann::json& errors) const {
  // Over the output times before the impact on the right wall (t > 0).
  double over_ritter = 0.0, s_mm = 0.0, s_ko = 0.0, signed_mm = 0.0, mass_change = 0.0;
  int n_free = 0, n_mm = 0, n_ko = 0;
  for (const auto& e : errors) {
    mass_change = std::max(mass_change, std::abs(e["mass_change"].get<double>()));
    const double t = e["t"].get<double>();
    if (e["impacted"].get<bool>() || t <= 0.0) continue;
    ++n_free;
    const double xf = e["x_front"].get<double>();
    over_ritter = std::max(over_ritter, (xf - a_) / (e["x_ritter"].get<double>() - a_));
    if (!e["x_mm"].is_null()) {
      const double d = (xf - e["x_mm"].get<double>()) / a_;
      s_mm += d * d;
      signed_mm += d;
      ++n_mm;
    }
    if (!e["x_ko"].is_null()) {
      const double d = (xf - e["x_ko"].get<double>()) / a_;
      s_ko += d * d;
      ++n_ko;
    }
  }
  nlohmann::json f;
  f["mass_change"] = mass_change;
  f["wall_penetrations"] = penetration_->count;
  f["min_wall_gap"] = std::isfinite(penetration_->min_gap) ? penetration_->min_gap / dx_ : 0.0;
  f["free_surge_outputs"] = n_free;
  f["front_max_over_ritter"] = n_free > 0 ? nlohmann::json(over_ritter) : nlohmann::json(nullptr);
  f["front_rms_martin_moyce"] = n_mm > 0 ? nlohmann::json(std::sqrt(s_mm / n_mm)) : nlohmann::json(nullptr);
  f["front_mean_martin_moyce"] = n_mm > 0 ? nlohmann::json(signed_mm / n_mm) : nlohmann::json(nullptr);
  f["front_rms_koshizuka_oka"] = n_ko > 0 ? nlohmann::json(std::sqrt(s_ko / n_ko)) : nlohmann::json(nullptr);
  double t_impact = -1.0;
  for (const auto& e : errors)
    if (e["impacted"].get<bool>()) {
      t_impact = e["t"].get<double>();
      break;
    }
  f["t_impact"] = t_impact >= 0.0 ? nlohmann::json(t_impact) : nlohmann::json(nullptr);
  if (!errors.empty()) f["x_front"] = errors.back()["x_front"];
  return f;
}

nlohmann::json DamBreakCase::save_state() const {
  // The rows as written (text already: exact); the penetrated particles by serial index.
  return {{"front_csv", csv_},
          {"wall_crossed", std::vector<std::uint64_t>(penetration_->crossed.begin(), penetration_->crossed.end())},
          {"min_wall_gap", encode_doubles({penetration_->min_gap})}};
}

void DamBreakCase::restore_state(const nlohmann::json& state) {
  if (!state.contains("front_csv") || !state["front_csv"].is_string() || state["front_csv"].get<std::string>().rfind(csv_, 0) != 0)
    throw std::invalid_argument("front_csv: missing or not front.csv's rows");
  if (!state.contains("wall_crossed") || !state["wall_crossed"].is_array())
    throw std::invalid_argument("wall_crossed: missing or not a list of particle indices");
  const double gap = state_double(state, "min_wall_gap");
  const auto crossed = state["wall_crossed"].get<std::vector<std::uint64_t>>();
  for (const std::uint64_t k : crossed)
    if (k >= n_fluid0_) throw std::invalid_argument("wall_crossed: " + std::to_string(k) + " is not a fluid particle");
  csv_ = state["front_csv"].get<std::string>();
  // The monitor has already seen the restart's first evaluation: the union and the smaller gap.
  penetration_->crossed.insert(crossed.begin(), crossed.end());
  penetration_->count = static_cast<long>(penetration_->crossed.size());
  penetration_->min_gap = std::min(penetration_->min_gap, gap);
}

void DamBreakCase::annotate(nlohmann::json& summary) const {
  summary["final_errors_note"] =
      "front_*: over output times before the front reaches the right wall, (x_front - x_ref)/a; "
      "front_max_over_ritter = max (x_front - a)/(2 sqrt(gH) t) (<= 1: below the Ritter bound); "
      "mass_change: largest relative change of the fluid mass; wall_penetrations: fluid particles that ever "
      "passed a wall (every RHS evaluation); min_wall_gap: closest approach to a wall surface [dx]; "
      "t_impact: first output time with the front at the right wall" +
      std::string(experiments_ ? "" : "; front_*_martin_moyce, front_rms_koshizuka_oka: null, the experiments have H = 2a");
  summary["column"] = {a_, H_};
  summary["experiments_compared"] = experiments_;
  summary["discretization"]["spacing"] = dx_;
  summary["discretization"]["wall_layers"] = wall_layers_;
  summary["particles_total"] = n_fluid0_ + n_wall_;
  summary["csv_files"] = {
      {"front.csv", "surge front x_front (rightmost fluid particle + dx/2) at every output time, T = t sqrt(2 g / a), "
                    "vs Ritter a + 2 sqrt(g H) t and the experiments of Martin and Moyce (1952, n^2 = 2) and Koshizuka "
                    "and Oka (1996) scaled to a (x_mm, x_ko; nan outside their time range, and everywhere for a "
                    "column with H != 2a)"}};
  if (experiments_) {
    summary["csv_files"]["front_martin_moyce_1952.csv"] = "Martin and Moyce (1952, n^2 = 2) surge front scaled to a and g of this run";
    summary["csv_files"]["front_koshizuka_oka_1996.csv"] = "Koshizuka and Oka (1996) surge front scaled to a and g of this run";
  }
  // Per particle-step with all particles (fluid and wall), as DualSPHysics reports its cost.
  const long steps = summary.value("steps", 0L);
  const double wall = summary.value("wall_seconds", 0.0);
  if (steps > 0)
    summary["us_per_particle_step"] = 1e6 * wall / (static_cast<double>(steps) * static_cast<double>(n_fluid0_ + n_wall_));
}

std::vector<PlotScript> DamBreakCase::plots(const OutputSink& out) const {
  // Reference points in dimensional form, one file per experiment, for gnuplot.
  const double tscale = 1.0 / std::sqrt(2.0 * g_ / a_);
  const auto reference = [&](const std::string& file, const auto& points) {
    std::ostringstream ref;
    ref << "t [s],x_front [m]\n" << std::setprecision(8);
    for (const auto& p : points) ref << p.T * tscale << ',' << p.Z * a_ << '\n';
    out.write(file, ref.str());
  };
  if (experiments_) {
    reference("front_martin_moyce_1952.csv", martin_moyce_1952_n2_2());
    reference("front_koshizuka_oka_1996.csv", koshizuka_oka_1996());
  }
  std::ostringstream s;
  s << gnuplot_csv_preamble("Dam-break surge front vs Ritter and experiments (sph-mol DamBreakCase)", 900, 640, 11, "front.png")
    << "set title 'Dam break (a = " << a_ << " m, H = " << H_ << " m): surge front x_{front}(t)'\n"
    << "set xlabel 't [s]'\nset ylabel 'x_{front} [m]'\nset key left top\nset grid\n"
    << "set key right bottom box opaque\n"
    << "set xrange [0:" << t_end_ << "]\nset yrange [" << a_ * 0.9 << ":" << Lx_ * 1.05 << "]\n"
    << "set samples 400\n"
    << "ritter(t) = " << a_ << " + 2.0 * sqrt(" << g_ << " * " << H_ << ") * t\n"
    << "plot 'front.csv' using 1:3 with linespoints pt 7 ps 0.6 lw 1.5 title 'SPH', \\\n"
    << "  ritter(x) with lines dt 2 lw 1.5 title 'Ritter a + 2 sqrt(gH) t (upper bound)', \\\n";
  if (experiments_)
    s << "  'front_martin_moyce_1952.csv' using 1:2 with points pt 5 ps 1 title 'Martin and Moyce 1952 (n^2 = 2)', \\\n"
      << "  'front_koshizuka_oka_1996.csv' using 1:2 with points pt 9 ps 1 title 'Koshizuka and Oka 1996', \\\n";
  s << "  " << Lx_ << " with lines lc rgb 'black' lw 1 title 'right wall'\n";
  return {{"front.png", s.str()}};
}

}  // namespace sphmol
