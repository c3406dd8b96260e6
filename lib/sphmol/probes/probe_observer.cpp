#include "sphmol/probes/probe_observer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <iomanip>
#include <sstream>

#include "sphmol/io/gnuplot.hpp"
#include "sphmol/kernels/registry.hpp"
#include "sphmol/probes/fluid_sampler.hpp"
#include "sphmol/probes/height_gauge.hpp"
#include "sphmol/probes/probe_terms.hpp"
#include "sphmol/run/gnuplot_preamble.hpp"

namespace sphmol {

namespace {

// Rewriting a file of many rows at every one of many samples would cost quadratic time: between
// output times a series is written at most this often (wall clock); at output times and at the end
// always.
constexpr double kFlushSeconds = 1.0;

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// A CSV number; NaN (no fluid there) is an empty cell, which pandas reads as NaN.
std::string cell(double v) {
  if (std::isnan(v)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

const char* const kAxis[3] = {"x", "y", "z"};
const char* const kVelocity[3] = {"u", "v", "w"};

template <int D>
std::string point_text(const geometry::Vec<D>& p) {
  std::string s = "(";
  for (int d = 0; d < D; ++d) s += (d ? ", " : "") + cell(p[d]);
  return s + ")";
}

std::string every_text(const ProbeConfig& p) {
  return p.every ? "every " + cell(*p.every) + " s from t = 0" : "at t = 0 and at the output times";
}

}  // namespace

template <int D>
ProbeObserver<D>::ProbeObserver(const Config& config, const SphSystem<D>& sys)
    : ProbeObserver(config, whole_piece(sys, sys.initial_state().data())) {}  // the state lives to the end of the call

template <int D>
ProbeObserver<D>::ProbeObserver(const Config& config, const OwnedPiece<D>& start)
    : output_times_(config.output.times), t_end_(config.time.t_end), h_(start.system->smoothing_length()) {
  const SphSystem<D>& sys = *start.system;
  const auto K = kernel_info<D>(sys.kernel_name());
  W_ = K.W;
  dWdr_ = K.dWdr;
  support_ = K.support;
  const auto& disc = config.discretization;
  model_.momentum_116 = disc.momentum == "symmetric_116";
  model_.viscous = disc.viscosity == "morris";
  model_.dynamic_viscosity = config.fluid.density * config.fluid.kinematic_viscosity;
  model_.morris_wall_velocity = disc.wall_model == "morris";
  model_.beta_max = disc.wall_beta_max;
  model_.artificial_viscosity = disc.artificial_viscosity.enabled;
  model_.pi = {disc.artificial_viscosity.alpha, disc.artificial_viscosity.beta, disc.artificial_viscosity.eta,
               disc.artificial_viscosity.band_width(), disc.artificial_viscosity.band_offset()};

  // Where the fluid can be sampled: the box of every particle at the start, widened by the kernel
  // support (periodic axes: the period).
  const auto& P = sys.particles();
  const auto& dom = sys.domain();
  const double* y0 = start.y;
  const auto& L = sys.layout();
  std::array<double, D> lo, hi;
  for (int d = 0; d < D; ++d) {
    lo[d] = std::numeric_limits<double>::infinity();
    hi[d] = -lo[d];
    const auto widen = [&](double x) {
      lo[d] = std::min(lo[d], x);
      hi[d] = std::max(hi[d], x);
    };
    for (const std::size_t i : start.fluid_rows) widen(y0[L.position(d) + i]);
    for (const std::size_t i : start.wall_rows) widen(P.x_ref[d][i]);
    lo[d] = start.min(lo[d]);
    hi[d] = start.max(hi[d]);
    if (dom.periodic[d]) {
      lo[d] = dom.lo[d];
      hi[d] = dom.hi[d];
    } else {
      lo[d] -= support_ * h_;
      hi[d] += support_ * h_;
    }
  }
  const auto box_text = [&] {
    std::string s;
    for (int d = 0; d < D; ++d) s += std::string(d ? " x " : "") + "[" + cell(lo[d]) + ", " + cell(hi[d]) + "]";
    return s;
  };
  const auto inside = [&](const std::vector<double>& p, int dims) {
    for (int d = 0; d < dims; ++d)
      if (!(p[d] >= lo[d] && p[d] <= hi[d])) return false;
    return true;
  };

  for (const ProbeConfig& c : config.probes) {
    Series s;
    s.cfg = c;
    std::ostringstream head;
    head << "t [s]";
    const std::string when = every_text(c);
    if (c.type == "point" || c.type == "line" || c.type == "plane") {
      const auto pts = c.sample_points();
      for (const auto& p : pts) {
        if (!inside(p, D)) {
          geometry::Vec<D> v;
          for (int d = 0; d < D; ++d) v[d] = p[d];
          throw ConfigError(c.where + ": " + (c.type == "point" ? "the point " : "the sample point ") + point_text<D>(v) +
                            " is outside the scene, whose particles (widened by the kernel support " + cell(support_ * h_) +
                            " m) span " + box_text());
        }
        geometry::Vec<D> v;
        for (int d = 0; d < D; ++d) v[d] = p[d];
        s.points.push_back(v);
      }
      if (c.type != "point")
        for (int d = 0; d < D; ++d) head << "," << kAxis[d] << " [m]";
      for (const auto& f : c.fields) {
        if (f == "p") head << ",p [Pa]";
        if (f == "rho") head << ",rho [kg/m^3]";
        if (f == "velocity")
          for (int d = 0; d < D; ++d) head << "," << kVelocity[d] << " [m/s]";
      }
      std::string fields;
      for (const auto& f : c.fields) fields += (fields.empty() ? "" : ", ") + f;
      if (c.type == "point")
        s.description = "probe " + c.name + ": " + fields + " of the fluid at " + point_text<D>(s.points[0]) +
                        " (Shepard-normalised SPH interpolation), " + when + "; empty cells: no fluid within the kernel support";
      else if (c.type == "line")
        s.description = "probe " + c.name + ": " + fields + " of the fluid at " + std::to_string(c.points[0]) +
                        " points from " + point_text<D>(s.points.front()) + " to " + point_text<D>(s.points.back()) +
                        ", one row per time and point (Shepard-normalised SPH interpolation), " + when +
                        "; empty cells: no fluid within the kernel support";
      else
        s.description = "probe " + c.name + ": " + fields + " of the fluid on a " + std::to_string(c.points[0]) + " x " +
                        std::to_string(c.points[1]) + " grid of the plane from " + point_text<D>(s.points.front()) +
                        ", one row per time and point (edge_1 fastest; Shepard-normalised SPH interpolation), " + when +
                        "; empty cells: no fluid within the kernel support";
    } else if (c.type == "height_gauge") {
      std::vector<double> at(c.at);
      if (!inside(at, D - 1))
        throw ConfigError(c.where + ": the gauge line at " + cell(at[0]) + (D == 3 ? ", " + cell(at[1]) : std::string()) +
                          " is outside the scene, whose particles (widened by the kernel support) span " + box_text());
      if (!c.range.empty() && (c.range[1] < lo[D - 1] || c.range[0] > hi[D - 1]))
        throw ConfigError(c.where + ": the gauge's range [" + cell(c.range[0]) + ", " + cell(c.range[1]) +
                          "] lies outside the scene, whose particles (widened by the kernel support) span " + box_text());
      // Every wall particle, to read the fluid's sum over the open part of the support (height_gauge.hpp).
      const auto known = std::find_if(walls_.begin(), walls_.end(), [](const BodyWalls<D>& w) { return w.body == kEveryWall; });
      s.walls = static_cast<std::size_t>(known - walls_.begin());
      if (known == walls_.end()) walls_.push_back(gather_body_walls<D>(start, kEveryWall));
      s.bottom = c.range.empty() ? lo[D - 1] : c.range[0];
      s.top = c.range.empty() ? hi[D - 1] : c.range[1];
      head << "," << (D == 2 ? "y" : "z") << "_surface [m]";
      s.description = "probe " + c.name + ": free-surface height on the vertical line " + (D == 2 ? "x = " + cell(at[0]) : "(x, y) = (" + cell(at[0]) + ", " + cell(at[1]) + ")") +
                      ": the highest point between " + cell(s.bottom) + " and " + cell(s.top) +
                      " m where the kernel sum of the fluid over the part of the support outside walls is 1/2 (scanned in "
                      "steps of h/4), " + when +
                      "; empty: no fluid on the line";
    } else {  // force
      std::uint64_t mine = 0;
      for (const std::size_t j : start.wall_rows) mine += P.body[j] == c.body_index ? 1 : 0;
      const bool any = start.sum(mine) > 0;
      if (!any) throw ConfigError(c.where + ": wall body '" + c.body + "' has no wall particles in the scene");
      const auto b = static_cast<std::size_t>(c.body_index);
      if (b < P.body_treatment.size() && P.body_treatment[b] == WallTreatment::repulsive)
        throw ConfigError(c.where + ": wall body '" + c.body + "' is repulsive: the force probe sums the SPH pair forces, "
                          "which its massless particles do not exert");
      const auto known = std::find_if(walls_.begin(), walls_.end(), [&](const BodyWalls<D>& w) { return w.body == c.body_index; });
      s.walls = static_cast<std::size_t>(known - walls_.begin());
      if (known == walls_.end()) walls_.push_back(gather_body_walls<D>(start, c.body_index));
      const char* unit = D == 3 ? "N" : D == 2 ? "N/m" : "N/m^2";
      for (int d = 0; d < D; ++d) head << ",F" << kAxis[d] << " [" << unit << "]";
      s.description = "probe " + c.name + ": force of the fluid on wall body " + c.body +
                      " (sum over fluid-wall pairs of the momentum equation's pair forces: pressure, eq " +
                      (model_.momentum_116 ? "116" : "117") + (model_.viscous ? ", Morris viscosity" : "") +
                      (model_.artificial_viscosity ? ", artificial viscosity" : "") + ")" +
                      (D == 2 ? ", per unit depth" : "") + ", " + when;
    }
    s.header = head.str() + "\n";
    series_.push_back(std::move(s));
  }
}

template <int D>
double ProbeObserver<D>::sample_time(const Series& s, long k) const {
  const double every = *s.cfg.every;
  const double tk = static_cast<double>(k) * every;
  // k * every rounds off (3 x 0.1 = 0.30000000000000004): a sample meant to fall on an output time
  // (or on t_end) does.
  for (const double to : output_times_)
    if (std::abs(tk - to) <= 1e-9 * every) return to;
  // The last sample is the end state: when t_end is not a multiple of every, the first multiple past
  // it is replaced by t_end.
  if (k > 0 && tk > t_end_ && static_cast<double>(k - 1) * every < t_end_ - 1e-9 * every) return t_end_;
  return tk;
}

template <int D>
double ProbeObserver<D>::next_time() const {
  double t = std::numeric_limits<double>::infinity();
  for (const auto& s : series_)
    if (s.cfg.every) {
      const double tk = sample_time(s, s.next_k);
      if (tk <= t_end_) t = std::min(t, tk);
    }
  return t;
}

template <int D>
std::size_t ProbeObserver<D>::columns(const Series& s) {
  std::size_t n = 0;
  for (const auto& f : s.cfg.fields) n += f == "velocity" ? D : 1;
  return n;
}

template <int D>
void ProbeObserver<D>::append_rows(Series& s, double t, const std::vector<double>& values) {
  if (on_sample) on_sample(s.cfg.name, t, values);
  std::string& rows = s.rows;
  const ProbeConfig& c = s.cfg;
  const std::string tt = cell(t);
  if (c.type == "point" || c.type == "line" || c.type == "plane") {
    const std::size_t n = columns(s);
    for (std::size_t q = 0; q < s.points.size(); ++q) {
      rows += tt;
      if (c.type != "point")
        for (int d = 0; d < D; ++d) (rows += ',') += cell(s.points[q][d]);
      for (std::size_t k = 0; k < n; ++k) (rows += ',') += cell(values[q * n + k]);
      rows += "\n";
    }
  } else {  // height gauge: one value; force: D
    rows += tt;
    for (const double v : values) (rows += ',') += cell(v);
    rows += "\n";
  }
  s.dirty = true;
}

template <int D>
std::unique_ptr<WallKernelSum<D>> ProbeObserver<D>::gauge_walls(const std::vector<std::size_t>& which, double t,
                                                                const Domain<D>& domain) const {
  for (const std::size_t k : which)
    if (series_[k].cfg.type == "height_gauge")
      return std::make_unique<WallKernelSum<D>>(walls_[series_[k].walls].walls, t, W_, h_, support_, domain);
  return nullptr;
}

template <int D>
void ProbeObserver<D>::sample(const std::vector<std::size_t>& which, const SphSystem<D>& sys, const double* y, double t) {
  if (which.empty()) return;
  const auto& P = sys.particles();
  const auto& L = sys.layout();
  const std::size_t nf = P.n_fluid;
  const std::vector<double>& rho = sys.density();
  const std::vector<double>& p = sys.pressure();
  std::array<const double*, D> xf{}, vf{};
  for (int d = 0; d < D; ++d) {
    xf[d] = y + L.position(d);
    vf[d] = y + L.velocity(d);
  }
  std::vector<double> volume(nf);
  // Fluid taken out of the run (run/outflow.hpp) has no volume: no probe sees it.
  for (std::size_t i = 0; i < nf; ++i) volume[i] = sys.is_retired(i) ? 0.0 : P.mass[i] / rho[i];
  const FluidSampler<D> fluid(xf, volume.data(), nf, W_, h_, support_, sys.domain());
  const auto walls = gauge_walls(which, t, sys.domain());
  for (const std::size_t k : which) {
    Series& s = series_[k];
    const ProbeConfig& c = s.cfg;
    std::vector<double> values;
    if (c.type == "point" || c.type == "line" || c.type == "plane") {
      for (const auto& x : s.points)
        for (const auto& f : c.fields) {
          if (f == "p") values.push_back(fluid.interpolate(x, p.data()));
          if (f == "rho") values.push_back(fluid.interpolate(x, rho.data()));
          if (f == "velocity")
            for (int d = 0; d < D; ++d) values.push_back(fluid.interpolate(x, vf[d]));
        }
    } else if (c.type == "height_gauge") {
      const std::vector<double> z = gauge_levels(s.bottom, s.top, 0.25 * h_);
      std::vector<double> sum(z.size());
      geometry::Vec<D> at = gauge_line(s);
      for (std::size_t q = 0; q < z.size(); ++q) {
        at[D - 1] = z[q];
        sum[q] = open_support_sum(fluid.kernel_sum(at), (*walls)(at));
      }
      values.push_back(surface_height(z, sum));
    } else {
      // Every particle as the RHS sees it: the fluid from the state, the walls at time t (position,
      // velocity and normal: a wall that follows a motion carries its velocity at t, not its
      // t = 0 one in P.v; a turning wall's normal has turned), by the rule of the solver's own
      // evaluation (rhs/sph_system.cpp: Particles::wall_state with each motion's frame at t) and of
      // the sample over ranks (sample_pieces), which must agree with this one to the bit.
      std::array<std::vector<double>, D> xa, va, na;
      WallForceState<D> st;
      for (int d = 0; d < D; ++d) {
        xa[d].resize(P.size());
        va[d].resize(P.size());
        na[d].assign(P.size(), 0.0);
        for (std::size_t i = 0; i < nf; ++i) {
          xa[d][i] = xf[d][i];
          va[d][i] = vf[d][i];
        }
        st.x[d] = xa[d].data();
        st.v[d] = va[d].data();
        st.n[d] = na[d].data();
      }
      const auto frames = P.motion_frames(t);
      for (std::size_t i = nf; i < P.size(); ++i) {
        const auto w = P.wall_state(i, frames, t);
        for (int d = 0; d < D; ++d) {
          xa[d][i] = w.x[d];
          va[d][i] = w.v[d];
          na[d][i] = w.n[d];
        }
      }
      st.rho = rho.data();
      st.p = p.data();
      st.c = sys.sound_speed().data();
      const auto F = wall_body_force<D>(P, st, c.body_index, dWdr_, h_, support_, sys.domain(), model_);
      values.assign(F.begin(), F.end());
    }
    append_rows(s, t, values);
  }
}

template <int D>
geometry::Vec<D> ProbeObserver<D>::gauge_line(const Series& s) {
  geometry::Vec<D> at{};
  for (int d = 0; d + 1 < D; ++d) at[d] = s.cfg.at[d];
  return at;
}

template <int D>
void ProbeObserver<D>::at_time_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t, const OutputSink& out) {
  // Every rank passes the sampling times alike; the same series are due on every rank.
  const std::vector<std::size_t> which = due(t);
  if (which.empty()) return;
  sample_pieces(which, whole, piece, t);
  if (now_seconds() - last_flush_ >= kFlushSeconds) flush(out);
}

template <int D>
void ProbeObserver<D>::at_output_time_pieces(const SphSystem<D>& whole, const OwnedPiece<D>& piece, double t, const OutputSink& out) {
  sample_pieces(at_outputs(), whole, piece, t);
  flush(out);  // as at_output: the files are complete at every output time (rank 0 alone writes)
}

template <int D>
std::vector<std::size_t> ProbeObserver<D>::at_outputs() const {
  std::vector<std::size_t> which;
  for (std::size_t k = 0; k < series_.size(); ++k)
    if (!series_[k].cfg.every) which.push_back(k);
  return which;
}

template <int D>
void ProbeObserver<D>::sample_pieces(const std::vector<std::size_t>& which, const SphSystem<D>& whole, const OwnedPiece<D>& piece,
                                     double t) {
  if (which.empty()) return;
  // Of `whole` only its domain: the ranks other than 0 hold none of its particles after the set-up.
  // The fluid's masses and viscosities from the rank's own system (its rows hold the scene's values),
  // the force probes' walls from their copies (walls_).
  const SphSystem<D>& local = *piece.system;
  const Particles<D>& LP = local.particles();
  const auto& LL = local.layout();
  const std::vector<double>& rho = local.density();
  const std::vector<double>& p = local.pressure();
  const std::vector<double>& cs = local.sound_speed();
  const double* y = piece.y;
  // The rank's own fluid in global-id order: positions and velocities from its state, volumes as
  // the serial sample makes them.
  const std::size_t n = piece.fluid_rows.size();
  std::array<std::vector<double>, D> x, v;
  std::array<const double*, D> xp{};
  std::vector<double> volume(n);
  for (int d = 0; d < D; ++d) {
    x[d].resize(n);
    v[d].resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      x[d][k] = y[LL.position(d) + piece.fluid_rows[k]];
      v[d][k] = y[LL.velocity(d) + piece.fluid_rows[k]];
    }
    xp[d] = x[d].data();
  }
  // Fluid taken out of the run (run/outflow.hpp) has no volume, as in the serial sample: its owner
  // still lists it.
  for (std::size_t k = 0; k < n; ++k)
    volume[k] = local.is_retired(piece.fluid_rows[k]) ? 0.0 : LP.mass[piece.fluid_rows[k]] / rho[piece.fluid_rows[k]];
  // The sampler's bins in the cells of the whole fluid's box, as the serial sampler bins the whole
  // fluid: its neighbours are visited in the serial order, by (cell, global id).
  const bool sampled = std::any_of(which.begin(), which.end(), [&](std::size_t k) { return series_[k].cfg.type != "force"; });
  std::optional<FluidSampler<D>> fluid;
  if (sampled) {
    auto box = PointBins<D>::bounds(xp, n);
    for (int d = 0; d < D; ++d) {
      box.first[d] = piece.min(box.first[d]);
      box.second[d] = piece.max(box.second[d]);
    }
    fluid.emplace(xp, volume.data(), n, W_, h_, support_, whole.domain(), box);
  }

  std::vector<ProbeTerms> terms(which.size());
  std::string missing;  // a force pair whose wall is not on the rank (the halo reaches a list radius)
  for (std::size_t w = 0; w < which.size(); ++w) {
    const Series& s = series_[which[w]];
    const ProbeConfig& c = s.cfg;
    ProbeTerms& T = terms[w];
    if (c.type == "point" || c.type == "line" || c.type == "plane") {
      // (point, cell, id) -> w and the sampled values, column by column.
      T.stride = 1 + columns(s);
      for (std::size_t q = 0; q < s.points.size(); ++q)
        fluid->weights(s.points[q], [&](int cell, std::size_t k, double wk) {
          T.keys.push_back({q, static_cast<std::uint64_t>(cell), static_cast<std::uint64_t>(piece.fluid_ids[k])});
          T.values.push_back(wk);
          const std::size_t row = piece.fluid_rows[k];
          for (const auto& f : c.fields) {
            if (f == "p") T.values.push_back(p[row]);
            if (f == "rho") T.values.push_back(rho[row]);
            if (f == "velocity")
              for (int d = 0; d < D; ++d) T.values.push_back(v[d][k]);
          }
        });
    } else if (c.type == "height_gauge") {
      // (level, cell, id) -> w.
      const std::vector<double> z = gauge_levels(s.bottom, s.top, 0.25 * h_);
      geometry::Vec<D> at = gauge_line(s);
      for (std::size_t q = 0; q < z.size(); ++q) {
        at[D - 1] = z[q];
        fluid->weights(at, [&](int cell, std::size_t k, double wk) {
          T.add({q, static_cast<std::uint64_t>(cell), static_cast<std::uint64_t>(piece.fluid_ids[k])}, {wk});
        });
      }
    } else {
      // (fluid id, neighbour number) -> the pair's D terms. The body's walls (their copy, in global-id
      // order) at t, every rank alike, in the serial bins: the neighbour numbers are the serial ones.
      // The fields of those near an owned fluid particle from the local system, whose halo holds them
      // as the RHS reads them.
      T.stride = D;
      const BodyWalls<D>& B = walls_[s.walls];
      const Particles<D>& PW = B.walls;
      // The walls' positions, velocities and normals at t by the serial sample's rule (the copy
      // holds the scene's motion table and each wall's motion index).
      const auto frames = PW.motion_frames(t);
      std::vector<typename Particles<D>::WallState> at_t(PW.size());
      for (std::size_t j = 0; j < PW.size(); ++j) at_t[j] = PW.wall_state(j, frames, t);
      const WallBodyBins<D> walls(PW, c.body_index, [&](int d, std::size_t j) { return at_t[j].x[d]; }, support_ * h_,
                                  whole.domain());
      const auto end = [&](std::size_t row) {
        WallPairEnd<D> e;
        e.rho = rho[row];
        e.p = p[row];
        e.c = model_.artificial_viscosity ? cs[row] : 0.0;
        return e;
      };
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t row_i = piece.fluid_rows[k];
        if (local.is_retired(row_i)) continue;  // taken out: pairs with no wall, as serially
        const auto i = static_cast<std::size_t>(piece.fluid_ids[k]);
        geometry::Vec<D> xi;
        WallPairEnd<D> a = end(row_i);
        for (int d = 0; d < D; ++d) {
          xi[d] = x[d][k];
          a.v[d] = v[d][k];
        }
        std::uint64_t seq = 0;
        walls.near(xi, [&](std::size_t w, double r, const std::array<double, D>& dx) {
          const std::uint64_t number = seq++;
          if (r == 0.0) return;  // as the serial sum
          const auto j = static_cast<std::int64_t>(B.ids[w]);  // its global id
          const auto at = std::lower_bound(piece.row_ids.begin(), piece.row_ids.end(), j);
          if (at == piece.row_ids.end() || *at != j) {
            if (missing.empty())
              missing = "wall particle " + std::to_string(j) + " near fluid particle " + std::to_string(i);
            return;
          }
          WallPairEnd<D> b = end(static_cast<std::size_t>(at - piece.row_ids.begin()));
          for (int d = 0; d < D; ++d) {
            b.v[d] = at_t[w].v[d];
            b.n[d] = at_t[w].n[d];
          }
          const std::array<double, D> f = wall_pair_force<D>(LP, row_i, PW, w, a, b, r, dx, dWdr_, h_, model_);
          T.keys.push_back({i, number, 0});
          T.values.insert(T.values.end(), f.begin(), f.end());
        });
      }
    }
  }
  // On every rank alike, rather than one rank leaving the others in the gather.
  if (std::any_of(which.begin(), which.end(), [&](std::size_t k) { return series_[k].cfg.type == "force"; }) &&
      piece.max(missing.empty() ? 0.0 : 1.0) > 0.0)
    throw std::logic_error("force probe over ranks: a rank lacks a wall neighbour of its own fluid" +
                           (missing.empty() ? std::string() : " (" + missing + ")"));
  std::vector<std::byte> mine;
  for (const ProbeTerms& T : terms) T.write(mine);
  const std::vector<std::byte> all = piece.gather_bytes(mine);
  if (piece.rank != 0) return;

  // Rank 0: every rank's terms, added in the serial order.
  std::vector<ProbeTerms> merged(which.size());
  for (std::size_t w = 0; w < which.size(); ++w) merged[w].stride = terms[w].stride;
  std::size_t at = 0;
  for (int r = 0; r < piece.ranks; ++r)
    for (ProbeTerms& T : merged) T.read(all, at);
  const auto walls = gauge_walls(which, t, whole.domain());
  for (std::size_t w = 0; w < which.size(); ++w) {
    Series& s = series_[which[w]];
    const ProbeConfig& c = s.cfg;
    const ProbeTerms& T = merged[w];
    const std::vector<std::size_t> order = T.order();
    std::vector<double> values;
    if (c.type == "point" || c.type == "line" || c.type == "plane") {
      // FluidSampler::interpolate, column by column.
      const std::size_t cols = columns(s);
      values.assign(s.points.size() * cols, 0.0);
      std::size_t o = 0;
      for (std::size_t q = 0; q < s.points.size(); ++q) {
        const std::size_t first = o;
        while (o < order.size() && T.keys[order[o]].a == q) ++o;
        for (std::size_t col = 0; col < cols; ++col) {
          double num = 0.0, den = 0.0;
          for (std::size_t e = first; e < o; ++e) {
            const double* tv = T.values.data() + order[e] * T.stride;
            num += tv[1 + col] * tv[0];
            den += tv[0];
          }
          values[q * cols + col] = den > 0.0 ? num / den : std::numeric_limits<double>::quiet_NaN();
        }
      }
    } else if (c.type == "height_gauge") {
      // FluidSampler::kernel_sum at each level.
      const std::vector<double> z = gauge_levels(s.bottom, s.top, 0.25 * h_);
      std::vector<double> sum(z.size(), 0.0);
      for (const std::size_t e : order) sum[T.keys[e].a] += T.values[e];
      geometry::Vec<D> at = gauge_line(s);
      for (std::size_t q = 0; q < z.size(); ++q) {
        at[D - 1] = z[q];
        sum[q] = open_support_sum(sum[q], (*walls)(at));
      }
      values.push_back(surface_height(z, sum));
    } else {
      std::array<double, D> force{};
      for (const std::size_t e : order)
        for (int d = 0; d < D; ++d) force[d] -= T.values[e * D + d];
      values.assign(force.begin(), force.end());
    }
    append_rows(s, t, values);
  }
}

template <int D>
void ProbeObserver<D>::flush(const OutputSink& out) {
  last_flush_ = now_seconds();
  if (!out.enabled) return;
  for (auto& s : series_)
    if (s.dirty) {
      out.write(file_name(s.cfg.name), s.header + s.rows);
      s.dirty = false;
    }
}

template <int D>
void ProbeObserver<D>::at_output(const SphSystem<D>& sys, const double* y, double t, const OutputSink& out) {
  sample(at_outputs(), sys, y, t);
  flush(out);
}

template <int D>
std::vector<std::size_t> ProbeObserver<D>::due(double t) {
  std::vector<std::size_t> which;
  for (std::size_t k = 0; k < series_.size(); ++k) {
    Series& s = series_[k];
    if (!s.cfg.every) continue;
    // The loop stops exactly on the sample time; a sample passed over (none should be) is not made up.
    bool is_due = false;
    while (sample_time(s, s.next_k) <= t_end_ && sample_time(s, s.next_k) <= t + 1e-12 * *s.cfg.every) {
      is_due = true;
      ++s.next_k;
    }
    if (is_due) which.push_back(k);
  }
  return which;
}

template <int D>
void ProbeObserver<D>::at_time(const SphSystem<D>& sys, const double* y, double t, const OutputSink& out) {
  sample(due(t), sys, y, t);
  if (now_seconds() - last_flush_ >= kFlushSeconds) flush(out);
}

template <int D>
void ProbeObserver<D>::at_stop(const OutputSink& out) {
  flush(out);
}

template <int D>
nlohmann::json ProbeObserver<D>::save_state() const {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& s : series_) list.push_back({{"name", s.cfg.name}, {"type", s.cfg.type}, {"rows", s.rows}, {"next_k", s.next_k}});
  return {{"probes", list}};
}

template <int D>
void ProbeObserver<D>::restore_state(const nlohmann::json& state, const OutputSink&) {
  // By name: a probe the checkpoint does not know starts empty, one it knows continues its rows. The
  // files are rewritten at the next output time (the folder is claimed only after this).
  for (const auto& e : state.at("probes")) {
    const std::string name = e.at("name").get<std::string>(), type = e.at("type").get<std::string>();
    for (auto& s : series_)
      if (s.cfg.name == name && s.cfg.type == type) {
        s.rows = e.at("rows").get<std::string>();
        s.next_k = e.at("next_k").get<long>();
        if (s.next_k < 0) throw std::invalid_argument("probe " + name + ": next_k must be >= 0");
        s.dirty = true;
      }
  }
}

namespace {

// Whether a row of `rows` (CSV lines) whose first cell is `t` (any row if `t` is empty) has a value in a
// column from `first` (0-based) on: a probe with no fluid near it has only empty cells there, and
// gnuplot refuses to draw a plot with no points.
bool has_values(const std::string& rows, std::size_t first, const std::string& t) {
  std::stringstream lines(rows);
  for (std::string line; std::getline(lines, line);) {
    std::stringstream cells(line);
    std::size_t k = 0;
    for (std::string cell; std::getline(cells, cell, ','); ++k) {
      if (k == 0 && !t.empty() && cell != t) break;
      if (k >= first && !cell.empty()) return true;
    }
  }
  return false;
}

}  // namespace

template <int D>
std::vector<PlotScript> ProbeObserver<D>::plots(const OutputSink&) const {
  std::vector<PlotScript> list;
  for (const auto& s : series_) {
    if (s.rows.empty()) continue;
    const ProbeConfig& c = s.cfg;
    // Line and plane probes draw their last sampled time, the others every time.
    const bool at_last = c.type == "line" || c.type == "plane";
    std::string t_last;
    if (at_last) {
      const std::size_t end = s.rows.rfind('\n', s.rows.size() - 2);
      const std::string last = s.rows.substr(end == std::string::npos ? 0 : end + 1);
      t_last = last.substr(0, last.find(','));
    }
    // No value to draw (no fluid reached the probe yet): no plot, its file says so with empty cells.
    if (!has_values(s.rows, at_last ? 1 + D : 1, t_last)) continue;
    const std::string csv = gnuplot_file(file_name(c.name)), png = "probe_" + c.name + ".png";
    // Column names from the header (without the newline).
    std::vector<std::string> cols;
    {
      std::stringstream h(s.header.substr(0, s.header.size() - 1));
      for (std::string col; std::getline(h, col, ',');) cols.push_back(col);
    }
    std::ostringstream g;
    g << std::setprecision(12);
    // Stacked panels get their own height; names keep their underscores (no enhanced text).
    const std::size_t panels = c.type == "point" ? cols.size() - 1 : c.type == "line" ? cols.size() - 1 - D : 1;
    g << gnuplot_csv_preamble("probe " + c.name + " (" + c.type + ") from " + file_name(c.name), 900,
                              static_cast<int>(std::max<std::size_t>(640, 300 * panels)), 11, png)
      << "set termoption noenhanced\n";
    if (c.type == "point" || c.type == "height_gauge" || c.type == "force") {
      // Each column against t: one panel per quantity (p, rho and speeds differ by orders of magnitude).
      const std::size_t n = cols.size() - 1;
      const bool same_units = c.type != "point";
      g << "set grid\nset xlabel " << gnuplot_text("t [s]") << "\n";
      if (same_units || n == 1) {
        g << "set title " << gnuplot_text("probe " + c.name) << "\nset ylabel " << gnuplot_text(cols[1].substr(cols[1].find(' ') + 1)) << "\nplot ";
        for (std::size_t k = 1; k <= n; ++k)
          g << (k > 1 ? ", \\\n  " : "") << csv << " using 1:" << k + 1 << " with linespoints pt 7 ps 0.4 title " << gnuplot_text(cols[k]);
        g << "\n";
      } else {
        g << "set multiplot layout " << n << ",1 title " << gnuplot_text("probe " + c.name) << "\n";
        for (std::size_t k = 1; k <= n; ++k)
          g << "set ylabel " << gnuplot_text(cols[k]) << "\nplot " << csv << " using 1:" << k + 1
            << " with linespoints pt 7 ps 0.4 notitle\n";
        g << "unset multiplot\n";
      }
    } else {
      // Line / plane: the last sampled time (t_last).
      const std::size_t first_field = 1 + D + 1;  // gnuplot column of the first field
      if (c.type == "line") {
        // Against the coordinate that varies most along the line.
        int axis = 0;
        for (int d = 1; d < D; ++d)
          if (std::abs(c.to[d] - c.from[d]) > std::abs(c.to[axis] - c.from[axis])) axis = d;
        const std::size_t n = cols.size() - first_field + 1;
        g << "set grid\nT = " << t_last << "\nset multiplot layout " << n << ",1 title "
          << gnuplot_text("probe " + c.name + " at t = " + t_last + " s") << "\nset xlabel " << gnuplot_text(cols[1 + axis]) << "\n";
        for (std::size_t k = first_field; k <= cols.size(); ++k)
          g << "set ylabel " << gnuplot_text(cols[k - 1]) << "\nplot " << csv << " using ($1 == T ? $" << 2 + axis << " : NaN):" << k
            << " with linespoints pt 7 ps 0.4 notitle\n";
        g << "unset multiplot\n";
      } else {
        // Plane: the first field as colours on the sample points in 3D.
        g << "T = " << t_last << "\nset view equal xyz\nset title "
          << gnuplot_text("probe " + c.name + ": " + cols[first_field - 1] + " at t = " + t_last + " s")
          << "\nset xlabel 'x [m]'\nset ylabel 'y [m]'\nset zlabel 'z [m]'\n"
          << "splot " << csv << " using ($1 == T ? $2 : NaN):3:4:" << first_field << " with points pt 7 ps 0.8 palette notitle\n";
      }
    }
    list.push_back({png, g.str()});
  }
  return list;
}

template <int D>
void ProbeObserver<D>::annotate(nlohmann::json& summary) const {
  for (const auto& s : series_) summary["csv_files"][file_name(s.cfg.name)] = s.description;
}

template class ProbeObserver<1>;
template class ProbeObserver<2>;
template class ProbeObserver<3>;

}  // namespace sphmol
