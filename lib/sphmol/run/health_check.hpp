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
        limits_(std::move(limits)), power_t_(t0), power_(body_force_power(y0, t0)) {}

  void operator()(double t, const double* y, double /*h*/) {
    const Scan s = scan(y);
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
  struct Scan {
    bool healthy = true;
    double rho_lo = std::numeric_limits<double>::infinity(), rho_hi = -std::numeric_limits<double>::infinity();
  };
  // The power of the body force on the fluid, sum_i m_i g(t) . v_i; in the walls' frame
  // (HealthLimits::WallFrame) that of g(t) - A(t) on the velocities relative to the frame.
  double body_force_power(const double* y, double t) const {
    const auto& L = sys_.layout();
    const auto& m = sys_.particles().mass;
    const auto& fr = limits_.frame;
    const double f = body_force_ramp_factor(t, limits_.g_ramp);
    double p = 0.0;
    for (int d = 0; d < D; ++d) {
      const double g = f * limits_.g[d] - (fr.on ? fr.A(d, t) : 0.0);
      if (g == 0.0) continue;
      const double V = fr.on ? fr.V(d, t) : 0.0;
      const double* v = y + L.velocity(d);
      double s = 0.0;  // serial: a sum must not depend on the thread count
      for (std::size_t i = 0; i < L.n; ++i) s += m[i] * (v[i] - V);
      p += g * s;
    }
    return p;
  }

  // The scene's physical bounds (run/health_limits.hpp), after the state is known to be finite.
  void physical(double t, const double* y, const Scan& s) {
    const auto& L = sys_.layout();
    const auto& m = sys_.particles().mass;
    const long n = static_cast<long>(L.n);
    // Serial: the kinetic energy (and so the message) must not depend on the thread count.
    // The kinetic energy relative to the walls' frame when there is one (health_limits.hpp).
    std::array<double, D> V{};
    if (limits_.frame.on)
      for (int d = 0; d < D; ++d) V[d] = limits_.frame.V(d, t);
    double vmax2 = 0.0, ke = 0.0;
    for (long i = 0; i < n; ++i) {
      double v2 = 0.0, w2 = 0.0;
      for (int d = 0; d < D; ++d) {
        const double v = y[L.velocity(d) + i], w = v - V[d];
        v2 += v * v;
        w2 += w * w;
      }
      vmax2 = std::max(vmax2, v2);
      ke += 0.5 * m[i] * w2;
    }
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
    const double p = body_force_power(y, t);
    work_ += 0.5 * (p + power_) * (t - power_t_);
    power_ = p;
    power_t_ = t;
    if (limits_.energy) {
      double el = 0.0;  // serial, as the kinetic energy
      if (limits_.elastic.kind != HealthLimits::Elastic::Kind::none) {
        const auto& rho = sys_.density();  // state order, as the masses
        const auto& own = sys_.particles().rest_density;
        for (std::size_t i = 0; i < L.n && i < rho.size(); ++i)
          el += m[i] * limits_.elastic.per_mass(rho[i], i < own.size() ? own[i] : 0.0);
      }
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
  // the message does not depend on the thread count), the fluid density range, and a copy of y into
  // candidate_, which becomes the last good state once every test has passed.
  Scan scan(const double* y) {
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
#pragma omp parallel reduction(|| : bad)
    {
      for (int d = 0; d < D; ++d) {
        const double* x = y + L.position(d);
        const double* v = y + L.velocity(d);
        const bool bounded = !dom.periodic[d];
#pragma omp for schedule(static) nowait
        for (long i = 0; i < n; ++i)
          bad |= !std::isfinite(x[i]) || !std::isfinite(v[i]) || (bounded && (x[i] < dom.lo[d] || x[i] > dom.hi[d]));
      }
      for_each_by_particle(static_cast<std::size_t>(ve), static_cast<std::size_t>(size), L.n,
                           [&](std::size_t k) { bad |= !std::isfinite(y[k]); });
#pragma omp for schedule(static) nowait reduction(min : lo) reduction(max : hi)
      for (long i = 0; i < nrho; ++i) {
        bad |= !(rho[i] > 0.0);
        lo = std::min(lo, rho[i]);
        hi = std::max(hi, rho[i]);
      }
      for_each_by_particle(0, static_cast<std::size_t>(size), L.n, [&](std::size_t k) { keep[k] = y[k]; });
    }
    return {!bad, lo, hi};
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
  double last_good_t_;
  double initial_cfl_;
  HealthLimits limits_;
  double power_t_, power_, work_ = 0.0;
};

}  // namespace sphmol
