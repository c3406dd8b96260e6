#pragma once
// The physical bounds of run/health_limits.hpp as the health checks apply them, serial
// (run/health_check.hpp) and over ranks (parallel/distributed_health_check.hpp): the per-particle
// sums they rest on, the body force's work accumulated from step to step, the tests and their
// messages. Both checks take the sums over the particles they hold and hand the totals here, so a
// run over ranks names the same cause as the serial run (its sums differ by round-off only: the
// bounds have generous slack).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "sphmol/core/state_layout.hpp"
#include "sphmol/physics/body_force.hpp"
#include "sphmol/run/health_limits.hpp"
#include "sphmol/time/blow_up.hpp"

namespace sphmol {

// Sums over fluid particles: the largest speed squared, the kinetic energy relative to the walls'
// frame, the elastic energy, and per direction sum_i m_i (v_i - V) for the body force's power.
template <int D>
struct PhysicalSums {
  double vmax2 = 0.0, ke = 0.0, el = 0.0;
  std::array<double, D> mv{};
  void add(const PhysicalSums& o) {
    vmax2 = std::max(vmax2, o.vmax2);
    ke += o.ke;
    el += o.el;
    for (int d = 0; d < D; ++d) mv[d] += o.mv[d];
  }
};

// Where the sums read a set of fluid particles: the state y in layout L, the masses, the densities
// of the latest evaluation and the particles' own rest densities, all in the state's order.
template <int D>
struct PhysicalInputs {
  std::array<double, D> V{};       // the walls' frame velocity at t (0 without a frame)
  const double* mass = nullptr;
  const double* rho = nullptr;     // null: no elastic energy
  long nrho = 0;
  const double* own = nullptr;     // Particles::rest_density; null when there is none
  long own_n = 0;
  // The particles' kinds: those taken out (Kind::Out, run/outflow.hpp) count as massless. Null: none is.
  const Kind* kind = nullptr;
};

template <int D>
class PhysicalBounds {
 public:
  // The largest block of particles sums() takes (its scratch array is of this length).
  static constexpr long kMaxBlock = 512;

  PhysicalBounds() = default;
  PhysicalBounds(HealthLimits limits, double t0) : limits_(std::move(limits)), power_t_(t0) {}

  const HealthLimits& limits() const { return limits_; }
  // Whether the sums need the densities (the elastic energy).
  bool elastic() const { return limits_.energy && limits_.elastic.kind != HealthLimits::Elastic::Kind::none; }
  std::array<double, D> frame_velocity(double t) const {
    std::array<double, D> V{};
    if (limits_.frame.on)
      for (int d = 0; d < D; ++d) V[d] = limits_.frame.V(d, t);
    return V;
  }

  // The sums over particles [lo, hi) (hi - lo <= kMaxBlock), in index order.
  PhysicalSums<D> sums(const StateLayout<D>& L, const double* y, const PhysicalInputs<D>& in, long lo, long hi) const {
    PhysicalSums<D> s;
    const auto mass = [&in](long i) { return in.kind && in.kind[i] == Kind::Out ? 0.0 : in.mass[i]; };
    for (long i = lo; i < hi; ++i) {
      double v2 = 0.0, w2 = 0.0;
      const double m = mass(i);
      for (int d = 0; d < D; ++d) {
        const double v = y[L.velocity(d) + i], w = v - in.V[d];
        v2 += v * v;
        w2 += w * w;
        s.mv[d] += m * w;
      }
      s.vmax2 = std::max(s.vmax2, v2);
      s.ke += 0.5 * m * w2;
    }
    // The elastic energy per unit mass of the block first (vectorised), then summed in order.
    const long e_hi = in.rho ? std::min(hi, in.nrho) : lo;
    if (e_hi > lo) {
      double u[kMaxBlock];
      if (in.own_n == 0 || in.own_n >= e_hi) {
        limits_.elastic.per_mass_block(in.rho + lo, in.own_n == 0 ? nullptr : in.own + lo, e_hi - lo, u);
      } else {
        for (long i = lo; i < e_hi; ++i) u[i - lo] = limits_.elastic.per_mass(in.rho[i], i < in.own_n ? in.own[i] : 0.0);
      }
      for (long i = lo; i < e_hi; ++i) s.el += mass(i) * u[i - lo];
    }
    return s;
  }
  // The sums over particles [0, n) in blocks of kMaxBlock, added in block order.
  PhysicalSums<D> sums(const StateLayout<D>& L, const double* y, const PhysicalInputs<D>& in, long n) const {
    PhysicalSums<D> s;
    for (long lo = 0; lo < n; lo += kMaxBlock) s.add(sums(L, y, in, lo, std::min(n, lo + kMaxBlock)));
    return s;
  }

  // The power of the body force on the fluid, sum_i m_i g(t) . v_i; in the walls' frame
  // (HealthLimits::WallFrame) that of g(t) - A(t) on the velocities relative to the frame.
  double power(const PhysicalSums<D>& s, double t) const {
    const auto& fr = limits_.frame;
    const double f = body_force_ramp_factor(t, limits_.g_ramp);
    double p = 0.0;
    for (int d = 0; d < D; ++d) {
      const double g = f * limits_.g[d] - (fr.on ? fr.A(d, t) : 0.0);
      if (g != 0.0) p += g * s.mv[d];
    }
    return p;
  }
  // The power at the start (t0 of the constructor), from the initial state's sums.
  void start(const PhysicalSums<D>& s0) { power_ = power(s0, power_t_); }
  // Work done on the fluid by the body force since t0 (trapezoidal rule over the accepted steps); in
  // the walls' moving frame, with the frame's inertial force.
  double work() const { return work_; }

  // Speed bound: exceeded by the largest speed squared?
  bool too_fast(double v2) const { return v2 > limits_.max_speed * limits_.max_speed; }
  BlowUp speed_blow_up(double t, long particle, double v2) const {
    return BlowUp(t, particle, "speed " + shown(std::sqrt(v2)) + " m/s above " + shown(limits_.max_speed) + " m/s, " +
                                   limits_.speed_reason);
  }
  // Density bound, on rho / rho0 (rho0: the particle's own rest density where the scene has several).
  bool density_bounded() const { return limits_.rho0 > 0.0; }
  bool outside_density(double ratio) const {
    return ratio - 1.0 > limits_.max_compression || 1.0 - ratio > limits_.max_expansion;
  }
  BlowUp density_blow_up(double t, long particle, double ratio) const {
    return BlowUp(t, particle, "density ratio rho/rho0 = " + shown(ratio) + " outside the weakly compressible range " +
                                   limits_.density_reason);
  }

  // After the speed and density tests of an accepted step at t: the body force's work up to t, then
  // the energy bound on the step's sums.
  void energy(double t, const PhysicalSums<D>& s) {
    const double p = power(s, t);
    work_ += 0.5 * (p + power_) * (t - power_t_);
    power_ = p;
    power_t_ = t;
    if (!limits_.energy) return;
    const double ke = s.ke, el = s.el;
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

  static std::string shown(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
  }

 private:
  HealthLimits limits_;
  double power_t_ = 0.0, power_ = 0.0, work_ = 0.0;
};

}  // namespace sphmol
