#pragma once
// Blow-up detection after every accepted step: NaN/Inf in the state, a fluid particle outside the
// domain in a non-periodic direction, density <= 0 in the latest RHS evaluation, or the CFL step
// collapsing below kCollapse times its initial value; then the physical bounds of the scene
// (run/health_limits.hpp): a speed above the scene's velocity scale or the sound speed, a density
// outside the EOS's weakly compressible range, kinetic energy beyond what the scene puts in. Throws
// BlowUp naming the time, the particle and the cause; keeps a copy of the last state that passed,
// for the run to write.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "sphmol/rhs/sph_system.hpp"
#include "sphmol/run/health_limits.hpp"
#include "sphmol/physics/body_force.hpp"
#include "sphmol/time/blow_up.hpp"
#include "sphmol/time/particle_split.hpp"

namespace sphmol {

template <int D>
class HealthCheck {
 public:
  static constexpr double kCollapse = 1e-6;

  HealthCheck(const SphSystem<D>& sys, const double* y0, double t0, HealthLimits limits = {})
      : sys_(sys), last_good_(y0, y0 + sys.size()), last_good_t_(t0), initial_cfl_(sys.stable_step()),
        limits_(std::move(limits)), power_t_(t0), power_(body_force_power(serial_sums(y0, t0, false), t0)) {}

  void operator()(double t, const double* y, double /*h*/) {
    const Scan s = scan(t, y);
    if (!s.healthy) report(t, y);
    physical(t, y, s);
    const double cfl = sys_.stable_step();
    if (std::isfinite(initial_cfl_) && !(cfl >= kCollapse * initial_cfl_))
      throw BlowUp(t, -1, "step-size collapse: the CFL step fell from " + std::to_string(initial_cfl_) + " s to " +
                              std::to_string(cfl) + " s");
    last_good_.swap(candidate_);  // the copy scan() made; the previous good state is reused next time
    last_good_t_ = t;
  }

  const std::vector<double>& last_good_state() const { return last_good_; }
  double last_good_time() const { return last_good_t_; }
  // Work done on the fluid by the body force since t0 (trapezoidal rule over the accepted steps); in
  // the walls' moving frame, with the frame's inertial force.
  double body_force_work() const { return work_; }

 private:
  // Sums over the fluid particles for the physical bounds: the largest speed squared, the kinetic
  // energy relative to the walls' frame, the elastic energy, and per direction sum_i m_i (v_i - V)
  // for the body force's power. Each sum is taken over fixed blocks of kSumBlock particles and the
  // block sums are added in block order, so the totals do not depend on the thread count while the
  // blocks are summed in parallel inside scan()'s region.
  static constexpr long kSumBlock = 512;
  struct Sums {
    double vmax2 = 0.0, ke = 0.0, el = 0.0;
    std::array<double, D> mv{};
    void add(const Sums& o) {
      vmax2 = std::max(vmax2, o.vmax2);
      ke += o.ke;
      el += o.el;
      for (int d = 0; d < D; ++d) mv[d] += o.mv[d];
    }
  };
  struct SumInputs {
    std::array<double, D> V{};     // the walls' frame velocity at t (0 without a frame)
    const double* rho = nullptr;   // state order; null: no elastic energy
    long nrho = 0;
  };
  SumInputs sum_inputs(double t, bool elastic) const {
    SumInputs in;
    if (limits_.frame.on)
      for (int d = 0; d < D; ++d) in.V[d] = limits_.frame.V(d, t);
    if (elastic && limits_.energy && limits_.elastic.kind != HealthLimits::Elastic::Kind::none) {
      const auto& rho = sys_.density();  // state order, as the masses
      in.rho = rho.data();
      in.nrho = std::min(static_cast<long>(sys_.layout().n), static_cast<long>(rho.size()));
    }
    return in;
  }
  Sums block_sums(const double* y, const SumInputs& in, long b) const {
    const auto& L = sys_.layout();
    const auto& m = sys_.particles().mass;
    const auto& own = sys_.particles().rest_density;
    const long lo = b * kSumBlock, hi = std::min(static_cast<long>(L.n), lo + kSumBlock);
    Sums s;
    for (long i = lo; i < hi; ++i) {
      double v2 = 0.0, w2 = 0.0;
      for (int d = 0; d < D; ++d) {
        const double v = y[L.velocity(d) + i], w = v - in.V[d];
        v2 += v * v;
        w2 += w * w;
        s.mv[d] += m[i] * w;
      }
      s.vmax2 = std::max(s.vmax2, v2);
      s.ke += 0.5 * m[i] * w2;
    }
    // The elastic energy per unit mass of the block first (vectorised), then summed in order.
    const long e_hi = std::min(hi, in.nrho);
    if (e_hi > lo) {
      double u[kSumBlock];
      const auto own_n = static_cast<long>(own.size());
      if (own_n == 0 || own_n >= e_hi) {
        limits_.elastic.per_mass_block(in.rho + lo, own_n == 0 ? nullptr : own.data() + lo, e_hi - lo, u);
      } else {
        for (long i = lo; i < e_hi; ++i) u[i - lo] = limits_.elastic.per_mass(in.rho[i], i < own_n ? own[i] : 0.0);
      }
      for (long i = lo; i < e_hi; ++i) s.el += m[i] * u[i - lo];
    }
    return s;
  }
  long sum_blocks() const { return (static_cast<long>(sys_.layout().n) + kSumBlock - 1) / kSumBlock; }
  Sums serial_sums(const double* y, double t, bool elastic) const {
    const SumInputs in = sum_inputs(t, elastic);
    Sums s;
    for (long b = 0; b < sum_blocks(); ++b) s.add(block_sums(y, in, b));
    return s;
  }
  struct Scan {
    bool healthy = true;
    double rho_lo = std::numeric_limits<double>::infinity(), rho_hi = -std::numeric_limits<double>::infinity();
    Sums sums;  // of the velocities and densities; meaningful only when healthy
  };
  // The power of the body force on the fluid, sum_i m_i g(t) . v_i; in the walls' frame
  // (HealthLimits::WallFrame) that of g(t) - A(t) on the velocities relative to the frame.
  double body_force_power(const Sums& s, double t) const {
    const auto& fr = limits_.frame;
    const double f = body_force_ramp_factor(t, limits_.g_ramp);
    double p = 0.0;
    for (int d = 0; d < D; ++d) {
      const double g = f * limits_.g[d] - (fr.on ? fr.A(d, t) : 0.0);
      if (g != 0.0) p += g * s.mv[d];
    }
    return p;
  }

  // The scene's physical bounds (run/health_limits.hpp), after the state is known to be finite.
  void physical(double t, const double* y, const Scan& s) {
    const auto& L = sys_.layout();
    const long n = static_cast<long>(L.n);
    // The kinetic energy relative to the walls' frame when there is one (health_limits.hpp), from
    // scan()'s block sums: the same for any thread count, and so the message.
    const double vmax2 = s.sums.vmax2, ke = s.sums.ke;
    if (vmax2 > limits_.max_speed * limits_.max_speed)
      for (long i = 0; i < n; ++i) {
        double v2 = 0.0;
        for (int d = 0; d < D; ++d) v2 += y[L.velocity(d) + i] * y[L.velocity(d) + i];
        if (v2 > limits_.max_speed * limits_.max_speed)
          throw BlowUp(t, i, "speed " + shown(std::sqrt(v2)) + " m/s above " + shown(limits_.max_speed) + " m/s, " +
                                 limits_.speed_reason);
      }
    if (limits_.rho0 > 0.0) {
      // Fluids of several rest densities (Particles::rest_density, state order): each particle against
      // its own rho0, read in state order; with one rho0 the extremes come from the scan.
      const auto& own = sys_.particles().rest_density;
      const double r0 = limits_.rho0;
      const auto rest = [&](long i) { return own.empty() ? r0 : own[static_cast<std::size_t>(i)]; };
      double lo = s.rho_lo / r0, hi = s.rho_hi / r0;  // of rho / rho0
      if (!own.empty()) {
        const auto& rho = sys_.density();
        const long nrho = std::min(n, static_cast<long>(rho.size()));
        lo = std::numeric_limits<double>::infinity();
        hi = -lo;
        for (long i = 0; i < nrho; ++i) {
          lo = std::min(lo, rho[i] / rest(i));
          hi = std::max(hi, rho[i] / rest(i));
        }
      }
      if (hi - 1.0 > limits_.max_compression || 1.0 - lo > limits_.max_expansion) {
        const auto& rs = sys_.density();  // state order, to name the particle
        for (std::size_t i = 0; i < L.n && i < rs.size(); ++i) {
          const double ratio = rs[i] / rest(static_cast<long>(i));
          if (ratio - 1.0 > limits_.max_compression || 1.0 - ratio > limits_.max_expansion)
            throw BlowUp(t, static_cast<long>(i), "density ratio rho/rho0 = " + shown(ratio) +
                                                      " outside the weakly compressible range " + limits_.density_reason);
        }
      }
    }
    const double p = body_force_power(s.sums, t);
    work_ += 0.5 * (p + power_) * (t - power_t_);
    power_ = p;
    power_t_ = t;
    if (limits_.energy) {
      const double el = s.sums.el;  // block sums, as the kinetic energy
      const double budget = limits_.energy_budget + std::max(0.0, work_);
      const double allowed = (1.0 + HealthLimits::kEnergySlack) * budget + limits_.energy_floor;
      // Energies of a D-dimensional model: per unit depth in 2D, per unit area in 1D.
      const char* unit = D == 3 ? " J" : D == 2 ? " J/m" : " J/m^2";
      if (ke + el > allowed)
        throw BlowUp(t, -1, "kinetic energy " + shown(ke) + unit + " plus elastic energy " + shown(el) + unit +
                                " exceeds what the scene puts in (" + shown(budget) + unit +
                                (limits_.frame.on ? ": in the walls' moving frame, initial kinetic, elastic and internal energy and the work of "
                                                      "the body force and the frame's inertial force"
                                                    : ": initial kinetic, elastic and internal energy, body-force work, "
                                                      "moving-wall bound M V^2/2") +
                                "; allowed " + shown(allowed) + unit + ")");
    }
  }

  static std::string shown(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
  }

  // Every per-particle pass after a step in one parallel region (its start and end are the only
  // synchronisations): the tests of report() (which then finds the first failure in its order, so
  // the message does not depend on the thread count), the fluid density range, the block sums of
  // the physical bounds, and a copy of y into candidate_, which becomes the last good state once
  // every test has passed.
  Scan scan(double t, const double* y) {
    const auto& L = sys_.layout();
    const auto& dom = sys_.domain();
    const long n = static_cast<long>(L.n), size = static_cast<long>(L.size()), ve = static_cast<long>(L.velocities_end());
    // The density in workspace order: the test is the same for every particle, and density() would
    // permute it serially after every step. Fluid entries come first in either order.
    const auto& rho = sys_.workspace_density();
    const long nrho = std::min(n, static_cast<long>(rho.size()));
    candidate_.resize(static_cast<std::size_t>(size));
    double* const keep = candidate_.data();
    bool bad = false;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    std::int64_t rho_ok = 1;
    const SumInputs in = sum_inputs(t, true);
    const long nb = sum_blocks();
    parts_.resize(static_cast<std::size_t>(nb));
    Sums* const part = parts_.data();
#pragma omp parallel reduction(|| : bad)
    {
      // Every test is an AND of comparisons without branches (into an integer as wide as a double,
      // which GCC vectorises), so that the loops vectorise: a value is finite when |v| <= the
      // largest double (false for NaN and Inf).
      constexpr double big = std::numeric_limits<double>::max();
      std::int64_t ok = 1;
      // Positions and velocities by the sums' blocks: the tests, the copy and the block's sums.
#pragma omp for schedule(static) nowait
      for (long b = 0; b < nb; ++b) {
        const long i0 = b * kSumBlock, i1 = std::min(n, i0 + kSumBlock);
        for (int d = 0; d < D; ++d) {
          const double* x = y + L.position(d);
          const double* v = y + L.velocity(d);
          double* kx = keep + L.position(d);
          double* kv = keep + L.velocity(d);
          const bool open = dom.periodic[d];
          const double xlo = dom.lo[d], xhi = dom.hi[d];
          for (long i = i0; i < i1; ++i) {
            const double xi = x[i], vi = v[i];
            ok &= static_cast<std::int64_t>((std::fabs(xi) <= big) & (std::fabs(vi) <= big) &
                                            (open | ((xi >= xlo) & (xi <= xhi))));
            kx[i] = xi;
            kv[i] = vi;
          }
        }
        part[b] = block_sums(y, in, b);
      }
      for_each_by_particle(static_cast<std::size_t>(ve), static_cast<std::size_t>(size), L.n, [&](std::size_t k) {
        ok &= static_cast<std::int64_t>(std::fabs(y[k]) <= big);
        keep[k] = y[k];
      });
      // simd: the extremes of positive densities do not depend on the order (and are not used when
      // some density is not positive).
#pragma omp for simd schedule(static) nowait reduction(min : lo) reduction(max : hi) reduction(& : rho_ok)
      for (long i = 0; i < nrho; ++i) {
        const double r = rho[i];
        rho_ok &= static_cast<std::int64_t>(r > 0.0);
        lo = std::min(lo, r);
        hi = std::max(hi, r);
      }
      bad = ok == 0;
    }
    Scan s{!bad && rho_ok != 0, lo, hi, {}};
    for (long b = 0; b < nb; ++b) s.sums.add(part[b]);  // in block order
    return s;
  }

  // Throws for the first particle that fails, in the order the tests are listed in the file comment.
  void report(double t, const double* y) const {
    const auto& L = sys_.layout();
    const auto& dom = sys_.domain();
    const std::size_t n = L.n;
    for (int d = 0; d < D; ++d) {
      const double* x = y + L.position(d);
      const double* v = y + L.velocity(d);
      for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(x[i]) || !std::isfinite(v[i]))
          throw BlowUp(t, static_cast<long>(i), std::string("NaN/Inf in the ") + (std::isfinite(x[i]) ? "velocity" : "position") +
                                                    " (component " + std::to_string(d) + ")");
        if (!dom.periodic[d] && (x[i] < dom.lo[d] || x[i] > dom.hi[d]))
          throw BlowUp(t, static_cast<long>(i), "particle left the domain in direction " + std::to_string(d) + " (x = " +
                                                    std::to_string(x[i]) + ", domain [" + std::to_string(dom.lo[d]) + ", " +
                                                    std::to_string(dom.hi[d]) + "])");
      }
    }
    for (std::size_t k = L.velocities_end(); k < L.size(); ++k)
      if (!std::isfinite(y[k])) throw BlowUp(t, static_cast<long>((k - L.velocities_end()) % n), "NaN/Inf in a state field");
    const auto& rho = sys_.density();
    for (std::size_t i = 0; i < n && i < rho.size(); ++i)
      if (!(rho[i] > 0.0)) throw BlowUp(t, static_cast<long>(i), "density <= 0 (rho = " + std::to_string(rho[i]) + ")");
  }

  const SphSystem<D>& sys_;
  std::vector<double> last_good_, candidate_;
  std::vector<Sums> parts_;  // scan()'s block sums
  double last_good_t_;
  double initial_cfl_;
  HealthLimits limits_;
  double power_t_, power_, work_ = 0.0;
};

}  // namespace sphmol
