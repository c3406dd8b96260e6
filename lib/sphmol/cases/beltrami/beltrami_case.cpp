#include "sphmol/cases/beltrami/beltrami_case.hpp"
#include "sphmol/cases/beltrami/beltrami_settings.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "sphmol/core/least_squares.hpp"
#include "sphmol/geometry/lattice.hpp"
#include "sphmol/physics/eos_tait.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/run/case_state.hpp"
#include "sphmol/run/gnuplot_preamble.hpp"
#include "sphmol/scenes/lattice_mass.hpp"
#include "sphmol/run/piece_reduction.hpp"

namespace sphmol {

namespace {

// The density the EOS gives the pressure p_rest + dp from, p_rest its pressure at rho0.
double density_for(const FluidConfig& f, double dp) {
  if (f.eos.type == "tait") return TaitLaw(f.eos.sound_speed, f.density, f.eos.gamma).density(dp);
  if (f.eos.type == "linear" || f.eos.type == "linear_relative") return f.density + dp / (f.eos.sound_speed * f.eos.sound_speed);
  throw std::invalid_argument("fluid.eos.type: the beltrami case needs a barotropic EOS (linear, linear_relative or tait)");
}

}  // namespace

std::unique_ptr<SphSystem<3>> BeltramiCase::build(const Config& config) {
  const auto& s = config.settings<BeltramiSettings>();
  const auto& disc = config.discretization;
  ref_.A = s.amplitudes[0];
  ref_.B = s.amplitudes[1];
  ref_.C = s.amplitudes[2];
  ref_.L = s.box[0];
  ref_.nu = config.fluid.kinematic_viscosity;
  ref_.rho = config.fluid.density;
  ref_.p0 = 0.0;
  const double L = s.box[0];
  const double dx = disc.particles_across > 0 ? L / disc.particles_across : disc.spacing;
  const long n = std::lround(L / dx);
  if (n <= 0 || std::abs(n * dx - L) > 1e-6 * L)
    throw std::invalid_argument("geometry.box: must be a whole number of particle spacings (" + std::to_string(dx) + " m)");
  spacing_ = dx;
  const double h = disc.smoothing_ratio * dx;
  const double rho0 = config.fluid.density;
  const double m = lattice_mass<3>(disc.particle_mass, disc.kernel, rho0, dx, h);
  geometry::Lattice<3> lattice;
  lattice.spacing = dx;
  Particles<3> P;
  lattice.for_each_in(geometry::Bounds<3>{{0.0, 0.0, 0.0}, {L, L, L}}, [&](const geometry::Vec<3>& p) {
    const auto u = ref_.velocity(p[0], p[1], p[2], 0.0);
    const double rho = density_for(config.fluid, ref_.pressure(p[0], p[1], p[2], 0.0));
    P.add(Kind::Fluid, {p[0], p[1], p[2]}, u, m * rho / rho0, rho);
  });
  Domain<3> domain;
  domain.lo = {0.0, 0.0, 0.0};
  domain.hi = {L, L, L};
  domain.periodic = {true, true, true};
  return assemble_system<3>(config, std::move(P), domain, dx);
}

double BeltramiCase::velocity_scale(const Config& config) const {
  const auto& a = config.settings<BeltramiSettings>().amplitudes;
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

nlohmann::json BeltramiCase::measure_pieces(const SphSystem<3>& whole, const OwnedPiece<3>& piece, double t,
                                            const OutputSink& out) {
  const auto& lay = piece.system->layout();
  const double* y = piece.y;
  const double decay = std::exp(-ref_.decay_rate() * t);
  const double amp = scale() * decay;
  const auto& m = piece.system->particles().mass;
  // Exact sums over the ranks' own fluid (run/piece_reduction.hpp): the serial values to the bit.
  PieceReduction r;
  const auto count = r.sum(), l1_sum = r.sum(), proj_sum = r.sum(), norm_sum = r.sum();
  for (const std::size_t i : piece.fluid_rows) {
    double x[3], v[3];
    for (int d = 0; d < 3; ++d) {
      x[d] = whole.domain().wrap(d, y[lay.position(d) + i]);
      v[d] = y[lay.velocity(d) + i];
    }
    const auto u0 = ref_.velocity(x[0], x[1], x[2], 0.0);
    double e2 = 0.0;
    for (int d = 0; d < 3; ++d) {
      e2 += (v[d] - u0[d] * decay) * (v[d] - u0[d] * decay);
      r.add(proj_sum, m[i] * v[d] * u0[d]);
      r.add(norm_sum, m[i] * u0[d] * u0[d]);
    }
    r.add(l1_sum, std::sqrt(e2));
    r.add(count, 1.0);
  }
  r.reduce(piece);
  const double n = r.value(count), proj = r.value(proj_sum), norm = r.value(norm_sum);
  double l1 = r.value(l1_sum);
  l1 /= n * amp;
  const double mode = norm > 0.0 ? proj / norm : 0.0;
  t_.push_back(t);
  mode_.push_back(mode);
  if (out.enabled) {
    std::ostringstream s;
    s << "t [s],mode_amplitude_sph [-],mode_amplitude_exact [-]\n" << std::setprecision(12);
    for (std::size_t k = 0; k < t_.size(); ++k) s << t_[k] << ',' << mode_[k] << ',' << std::exp(-ref_.decay_rate() * t_[k]) << '\n';
    out.write("decay.csv", s.str());
  }
  return {{"t", t}, {"L1_velocity", l1}, {"mode_amplitude_rel_error", std::abs(mode - decay) / decay}};
}

nlohmann::json BeltramiCase::final_errors(const nlohmann::json& errors) const {
  nlohmann::json f = Case<3>::final_errors(errors);
  const double exact = ref_.decay_rate();
  f["decay_rate_exact"] = exact;
  bool positive = t_.size() >= 2;
  for (const double a : mode_) positive = positive && a > 0.0;
  if (positive) {
    // Least-squares slope of ln a(t) over the output times.
    std::vector<double> ln_a(mode_.size());
    for (std::size_t k = 0; k < mode_.size(); ++k) ln_a[k] = std::log(mode_[k]);
    const double rate = -least_squares_slope(t_, ln_a);
    f["decay_rate"] = rate;
    f["decay_rate_rel_error"] = std::abs(rate - exact) / exact;
  } else {
    f["decay_rate"] = nullptr;  // fewer than two output times, or a mode that lost its sign: no fit
  }
  return f;
}

nlohmann::json BeltramiCase::save_state() const {
  return {{"t", encode_doubles(t_)}, {"mode_amplitude", encode_doubles(mode_)}};
}

void BeltramiCase::restore_state(const nlohmann::json& state) {
  restore_columns(state, {{"t", &t_}, {"mode_amplitude", &mode_}});
}

void BeltramiCase::annotate(nlohmann::json& summary) const {
  summary["beltrami"] = {{"side", ref_.L},
                         {"amplitudes", {ref_.A, ref_.B, ref_.C}},
                         {"wavenumber", ref_.wavenumber()},
                         {"Re", scale() * ref_.L / ref_.nu},
                         {"decay_rate_exact", ref_.decay_rate()}};
  summary["discretization"]["spacing"] = spacing_;
  summary["csv_files"]["decay.csv"] =
      "the ABC mode's amplitude (projection of the particle velocities on the mode, 1 at t = 0) at every output time "
      "vs the exact e^{-nu k^2 t}";
}

// decay.png: the mode amplitude against the exact e^{-nu k^2 t}, on a log scale.
std::vector<PlotScript> BeltramiCase::plots(const OutputSink&) const {
  if (t_.empty()) return {};
  std::ostringstream s;
  s << std::setprecision(12)
    << gnuplot_csv_preamble("ABC flow decay: SPH mode amplitude vs exact (sph-mol BeltramiCase)", 900, 640, 11, "decay.png")
    << "set title \"Arnold-Beltrami-Childress flow: mode amplitude (points SPH, line exact e^{-nu k^2 t}, nu k^2 = "
    << std::setprecision(4) << ref_.decay_rate() << " 1/s)\" noenhanced\n"
    << "set xlabel 't [s]'\nset ylabel 'amplitude [-]'\nset logscale y\nset grid\nset key top right\n"
    << "plot 'decay.csv' using 1:3 with lines lw 2 title 'exact', \\\n"
    << "  'decay.csv' using 1:2 with points pt 7 ps 1.2 title 'SPH'\n";
  return {{"decay.png", s.str()}};
}

}  // namespace sphmol
