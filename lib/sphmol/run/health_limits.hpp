#pragma once
// Physical bounds for the per-step health check (run/health_check.hpp), derived from the scene so
// that an unstable run ends as a blow-up instead of completing with a wrong answer:
//  - speed: |v| <= kSpeedFactor U, with U the scene's velocity scale (wall or lid speed, Taylor-Green
//    amplitude, Poiseuille centre-line speed F l^2 / (8 nu), free-fall speed sqrt(2 g H) of a column),
//    and |v| < c (Mach 1) in a weakly compressible fluid, whose EOS models a liquid at Mach << 1;
//  - density: |rho/rho0 - 1| <= max(kDensityFloor, kDensityFactor delta), delta = (U/c)^2 the expected
//    compressibility (Monaghan 1994: delta rho / rho ~ M^2). Only compression is bounded where a free
//    surface is (summation density is short of rho0 there, and a splash is free to expand);
//  - mechanical energy: with no energy input the fluid cannot gain kinetic plus elastic energy. The
//    elastic energy is what the EOS stores in a compressed (or stretched) particle, m times
//    u(rho) = int_rho0^rho p(r) / r^2 dr >= 0; a column that starts at its hydrostatic density
//    turns it into motion where it is free to expand (the dam break). The inputs are the initial
//    kinetic and elastic energy, the internal energy (energy equation), the work of the body force
//    (accumulated per step from sum_i m_i g(t) . v_i) and moving walls, whose largest speed V (of any
//    wall particle at any time, SphSystem::max_wall_speed) bounds the fluid's by the maximum principle
//    (KE <= M V^2 / 2). That bound does not hold for walls that keep doing pressure work (a tank
//    shaken at resonance). So when every wall particle follows one rigid translation (a translating
//    or oscillating tank, all walls of the scene), the energies are measured in the walls' frame
//    instead: there the walls are at rest and the frame's acceleration A(t) acts as a body force
//    -A(t), whose work is accumulated with the body force's (Landau & Lifshitz 1976, §39: the
//    inertial force -m A in a translating frame). KE + E_el may exceed this budget by
//    kEnergySlack of it plus kEnergyFloor M U^2 / 2 (the time discretisation of the work integral).
// Ideal-gas scenes (shock tubes) skip the speed and density bounds: supersonic flow and 4:1
// compression are the physics there.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numbers>
#include <string>
#include <type_traits>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/rhs/sph_system.hpp"
#include "sphmol/run/owned_piece.hpp"
#include "sphmol/run/piece_reduction.hpp"
#include "sphmol/run/whole_piece.hpp"

namespace sphmol {

struct HealthLimits {
  static constexpr double kSpeedFactor = 10.0;
  static constexpr double kDensityFactor = 10.0;
  static constexpr double kDensityFloor = 0.2;
  static constexpr double kEnergySlack = 0.1;
  static constexpr double kEnergyFloor = 1e-3;

  double max_speed = std::numeric_limits<double>::infinity();  // |v| above this is a blow-up
  std::string speed_reason;                                     // what max_speed is, for the message
  double rho0 = 0.0;                                            // 0: no density bound
  double max_compression = std::numeric_limits<double>::infinity();  // on rho/rho0 - 1
  double max_expansion = std::numeric_limits<double>::infinity();    // on 1 - rho/rho0
  std::string density_reason;
  bool energy = false;          // bound the kinetic energy
  double energy_budget = 0.0;   // initial kinetic + internal energy and the moving-wall bound [J (per unit depth)]
  double energy_floor = 0.0;    // absolute slack [J]
  std::array<double, 3> g{};    // body force per unit mass, for its work
  double g_ramp = 0.0;

  // The walls' common translating frame, when every wall particle follows one translation or
  // oscillation (see the file comment): its velocity V(t) and acceleration A(t) (WallMotion's rules).
  struct WallFrame {
    bool on = false;
    bool oscillation = false;      // else a constant translation
    std::array<double, 3> velocity{}, amplitude{};
    double omega = 0.0, phase = 0.0;  // oscillation: 2 pi f [rad/s], phase [rad]
    double V(int d, double t) const {
      return oscillation ? amplitude[d] * omega * std::cos(omega * t + phase) : velocity[d];
    }
    double A(int d, double t) const {
      return oscillation ? -amplitude[d] * omega * omega * std::sin(omega * t + phase) : 0.0;
    }
  } frame;

  // u(rho) = int_rho0^rho p / r^2 dr of the weakly compressible EOS [J/kg], 0 without one. The
  // constant part of p (p = c^2 rho, a background pressure) does no net work and is left out.
  struct Elastic {
    enum class Kind { none, linear, tait } kind = Kind::none;
    double rho0 = 0.0, c2 = 0.0, gamma = 7.0;
    bool clamp_negative = false;  // tait: p = max(p, 0), so no energy is stored below rho0
    // own_rho0 > 0: the particle's own rest density (Particles::rest_density) instead of rho0.
    double per_mass(double rho, double own_rho0 = 0.0) const {
      if (kind == Kind::none || !(rho > 0.0)) return 0.0;
      const double rho0 = own_rho0 > 0.0 ? own_rho0 : this->rho0;
      if (kind == Kind::linear) return c2 * (std::log(rho / rho0) + rho0 / rho - 1.0);  // p = c^2 (rho - rho0)
      if (clamp_negative && rho < rho0) return 0.0;
      // p = B((rho/rho0)^gamma - 1), B = c^2 rho0 / gamma (Tait)
      const double B = c2 * rho0 / gamma, x = rho / rho0;
      // A whole exponent (gamma = 7 as usual) by multiplication: this runs for every particle and step.
      double xp = 1.0;
      if (gamma == std::floor(gamma) && gamma >= 1.0 && gamma <= 16.0)
        for (int k = 1; k < static_cast<int>(gamma); ++k) xp *= x;
      else
        xp = std::pow(x, gamma - 1.0);
      return B * ((xp - 1.0) / ((gamma - 1.0) * rho0) + 1.0 / rho - 1.0 / rho0);
    }
    // per_mass(rho[i], own ? own[i] : 0) for i in [0, n) into out, bit for bit. The health check
    // evaluates it for every particle after every step: the Tait form with a whole exponent is
    // written without per-particle branches, in short runs of particles, so that it vectorises.
    void per_mass_block(const double* rho, const double* own, long n, double* out) const {
      if (kind != Kind::tait || !(gamma == std::floor(gamma) && gamma >= 1.0 && gamma <= 16.0)) {
        for (long i = 0; i < n; ++i) out[i] = per_mass(rho[i], own ? own[i] : 0.0);
        return;
      }
      // The members in locals: out may alias them as far as the compiler knows, which would reload
      // them in every iteration and keep the loops from vectorising.
      const int g = static_cast<int>(gamma);
      const double c2_ = c2, gamma_ = gamma, rho0_ = rho0;
      const bool clamp = clamp_negative;
      constexpr long kRun = 64;
      for (long c = 0; c < n; c += kRun) {
        const long m = std::min(kRun, n - c);
        const double* const r = rho + c;
        double r0[kRun], x[kRun], xp[kRun];
        for (long k = 0; k < m; ++k) {
          r0[k] = own && own[c + k] > 0.0 ? own[c + k] : rho0_;
          x[k] = r[k] / r0[k];
          xp[k] = g > 1 ? x[k] : 1.0;  // per_mass's 1.0 * x, exact
        }
        for (int p = 2; p < g; ++p)  // per_mass's further factors, in its order
          for (long k = 0; k < m; ++k) xp[k] *= x[k];
        for (long k = 0; k < m; ++k) {
          const double B = c2_ * r0[k] / gamma_;
          const double u = B * ((xp[k] - 1.0) / ((gamma_ - 1.0) * r0[k]) + 1.0 / r[k] - 1.0 / r0[k]);
          const double floor = clamp ? r0[k] : 0.0;  // per_mass's zero below rho0 when clamped
          out[c + k] = r[k] > 0.0 && r[k] >= floor ? u : 0.0;
        }
      }
    }
  } elastic;
};

// The frame of the walls when all of them (and at least one) follow one moving rigid translation:
// the same translation or oscillation (not `stationary`, which leaves the walls in place), and no
// generated (ghost) walls, which stay where the domain is. Collective over the ranks of `piece` (the
// ranks' particles as the run starts, run/start_piece.hpp): each rank looks at its own walls.
template <int D>
HealthLimits::WallFrame common_wall_frame(const OwnedPiece<D>& piece) {
  HealthLimits::WallFrame f;
  const SphSystem<D>& sys = *piece.system;
  const auto& P = sys.particles();
  const auto same = [](const WallMotion<D>& a, const WallMotion<D>& b) {
    bool s = a.kind == b.kind && a.frequency == b.frequency && a.phase == b.phase;
    for (int d = 0; d < D; ++d) s = s && a.velocity[d] == b.velocity[d] && a.amplitude[d] == b.amplitude[d];
    return s;
  };
  // This rank: whether all its walls translate alike, and the motion of its first wall (-1: none).
  std::int32_t first = -1;
  std::uint64_t unlike = 0;
  for (const std::size_t i : piece.wall_rows) {
    const std::int32_t k = P.motion[i];
    if (k < 0) {
      unlike = 1;
      break;
    }
    const WallMotion<D>& m = P.motions[static_cast<std::size_t>(k)];
    if ((m.kind != WallMotionKind::translation && m.kind != WallMotionKind::oscillation) || m.stationary) {
      unlike = 1;
      break;
    }
    if (first < 0) first = k;
    else if (k != first && !same(m, P.motions[static_cast<std::size_t>(first)])) {
      unlike = 1;
      break;
    }
  }
  // Over the ranks: every rank's first motion, and whether any rank has walls unlike its own first.
  std::vector<std::byte> mine(sizeof first);
  std::memcpy(mine.data(), &first, sizeof first);
  const std::vector<std::byte> all = piece.all_gather_bytes(mine);
  const std::uint64_t unlike_anywhere = piece.sum(unlike);
  if (sys.has_generator() || unlike_anywhere > 0) return f;
  const WallMotion<D>* frame = nullptr;
  for (std::size_t r = 0; r * sizeof first < all.size(); ++r) {
    std::int32_t k = -1;
    std::memcpy(&k, all.data() + r * sizeof first, sizeof first);
    if (k < 0) continue;  // a rank with no walls
    const WallMotion<D>& m = P.motions[static_cast<std::size_t>(k)];
    if (!frame) frame = &m;
    else if (!same(m, *frame)) return f;
  }
  if (!frame) return f;  // no walls at all
  f.on = true;
  f.oscillation = frame->kind == WallMotionKind::oscillation;
  for (int d = 0; d < D; ++d) {
    f.velocity[d] = frame->velocity[d];
    f.amplitude[d] = frame->amplitude[d];
  }
  f.omega = 2.0 * std::numbers::pi * frame->frequency;
  f.phase = frame->phase;
  return f;
}

// What the limits read from the whole scene at the start: the fluid's mass, kinetic energy (in the
// walls' frame), internal and elastic energy, its largest speed, and the walls' frame and largest
// speed. A run over ranks sums them over the ranks' particles (health_sums, elastic_energy_total),
// exactly: every rank makes the serial run's limits, to the bit.
struct HealthSums {
  HealthLimits::WallFrame frame;
  double mass = 0.0, ke0 = 0.0, e0 = 0.0, el0 = 0.0, v0max = 0.0, wall_speed = 0.0;
};
static_assert(std::is_trivially_copyable_v<HealthSums>);

// The elastic energy of the config's EOS (none for an ideal gas).
inline HealthLimits::Elastic elastic_energy(const Config& c) {
  HealthLimits::Elastic el;
  if (c.fluid.eos.type == "ideal_gas") return el;
  const auto& eos = c.fluid.eos;
  el.kind = eos.type == "tait" ? HealthLimits::Elastic::Kind::tait : HealthLimits::Elastic::Kind::linear;
  el.rho0 = c.fluid.density;
  el.c2 = eos.sound_speed * eos.sound_speed;
  el.gamma = eos.gamma;
  el.clamp_negative = eos.clamp_negative;
  return el;
}

// The sums of the state the run starts from (collective over the ranks of `start`, the ranks'
// particles as the run starts, run/start_piece.hpp; a serial run: the whole scene), exact in any
// order (run/piece_reduction.hpp), so every rank count has the serial sums to the bit. Fluid taken
// out (run/outflow.hpp) is no part of the fluid's energy. The elastic energy needs an evaluation's
// densities: elastic_energy_total(), added once the run's first evaluation has been made.
template <int D>
HealthSums health_sums(const OwnedPiece<D>& start) {
  HealthSums s;
  s.frame = common_wall_frame(start);
  const SphSystem<D>& sys = *start.system;
  const auto& L = sys.layout();
  const auto& m = sys.particles().mass;
  const double* y0 = start.y;
  PieceReduction r;
  const auto mass = r.sum(), ke0 = r.sum(), e0 = r.sum(), v0max = r.largest(), wall_speed = r.largest();
  for (const std::size_t i : start.fluid_rows) {
    if (sys.is_retired(i)) continue;
    double v2 = 0.0, w2 = 0.0;  // w: relative to the walls' frame when there is one
    for (int d = 0; d < D; ++d) {
      const double v = y0[L.velocity(d) + i], w = v - (s.frame.on ? s.frame.V(d, 0.0) : 0.0);
      v2 += v * v;
      w2 += w * w;
    }
    r.add(mass, m[i]);
    r.add(ke0, 0.5 * m[i] * w2);
    r.add(v0max, std::sqrt(v2));
    if (L.has_energy) r.add(e0, m[i] * y0[L.energy() + i]);
  }
  // Moving walls can feed the fluid up to 1/2 M V^2, V the largest speed of any wall (a lid, a plate,
  // a rotating wall's max |omega r|): each rank's walls, and the generated ones alike on every rank.
  r.add(wall_speed, sys.max_wall_speed());
  r.reduce(start);
  s.mass = r.value(mass);
  s.ke0 = r.value(ke0);
  s.e0 = r.value(e0);
  s.v0max = std::max(0.0, r.value(v0max));  // no fluid: -infinity
  s.wall_speed = r.value(wall_speed);
  return s;
}

// The elastic energy sum_i m_i e(rho_i) of the fluid particles i < n of P (fluid first) not taken
// out, with the densities `rho` of an evaluation and each particle's own rest density
// (Particles::rest_density; empty: the fluid's), exact over the ranks of `ranks`
// (run/piece_reduction.hpp): a rank's owned particles, or a serial run's whole scene.
template <int D>
double elastic_energy_total(const HealthLimits::Elastic& elastic, const Particles<D>& P, std::size_t n,
                            const std::vector<double>& rho, const PieceCollectives& ranks) {
  PieceReduction r;
  const auto el = r.sum();
  const auto& own = P.rest_density;
  for (std::size_t i = 0; i < n; ++i)
    if (P.kind[i] != Kind::Out) r.add(el, P.mass[i] * elastic.per_mass(rho[i], i < own.size() ? own[i] : 0.0));
  r.reduce(ranks);
  return r.value(el);
}

// The elastic energy of a serial run's whole scene at its latest evaluation.
template <int D>
double elastic_energy_total(const HealthLimits::Elastic& elastic, const SphSystem<D>& sys) {
  return elastic_energy_total(elastic, sys.particles(), sys.layout().n, sys.density(), one_rank_collectives());
}

// A serial run's sums: the whole scene at y0, with the densities of its evaluation at y0.
template <int D>
HealthSums health_sums(const Config& c, const SphSystem<D>& sys, const double* y0) {
  HealthSums s = health_sums(whole_piece(sys, y0));
  s.el0 = elastic_energy_total(elastic_energy(c), sys);
  return s;
}

// `velocity_scale` and `free_surface` come from the case (Case::velocity_scale, Case::free_surface).
template <int D>
HealthLimits health_limits(const Config& c, double velocity_scale, bool free_surface, const HealthSums& s) {
  HealthLimits lim;
  lim.frame = s.frame;
  const bool ideal_gas = c.fluid.eos.type == "ideal_gas";
  const double U = std::max(velocity_scale, s.v0max);
  if (!ideal_gas && U > 0.0) {
    const double cs = c.fluid.eos.sound_speed;
    char buf[160];
    if (HealthLimits::kSpeedFactor * U < cs) {
      lim.max_speed = HealthLimits::kSpeedFactor * U;
      std::snprintf(buf, sizeof buf, "%g times the scene's velocity scale U = %g m/s", HealthLimits::kSpeedFactor, U);
    } else {
      lim.max_speed = cs;
      std::snprintf(buf, sizeof buf, "the sound speed c = %g m/s (Mach 1; the weakly compressible EOS needs Mach << 1)", cs);
    }
    lim.speed_reason = buf;
    const double delta = (U / cs) * (U / cs);
    const double bound = std::max(HealthLimits::kDensityFloor, HealthLimits::kDensityFactor * delta);
    lim.rho0 = c.fluid.density;
    lim.max_compression = bound;
    const bool short_support = c.discretization.density != "continuity" && c.discretization.boundary == "virtual_repulsive";
    if (!free_surface && !short_support) lim.max_expansion = bound;
    std::snprintf(buf, sizeof buf, "|rho/rho0 - 1| <= %g (max(%g, %g (U/c)^2), U = %g m/s, c = %g m/s)", bound,
                  HealthLimits::kDensityFloor, HealthLimits::kDensityFactor, U, cs);
    lim.density_reason = buf;
  }
  lim.elastic = elastic_energy(c);
  lim.energy = true;
  // In the walls' frame the walls do no work; otherwise their maximum-principle bound.
  lim.energy_budget = s.ke0 + s.el0 + s.e0 + (lim.frame.on ? 0.0 : 0.5 * s.mass * s.wall_speed * s.wall_speed);
  // Zero-budget scenes: measured against the scene's velocity scale, or the sound speed without one.
  const double scale = U > 0.0 ? U : (ideal_gas ? 0.0 : 0.01 * c.fluid.eos.sound_speed);
  lim.energy_floor = HealthLimits::kEnergyFloor * 0.5 * s.mass * scale * scale;
  for (int d = 0; d < D && d < static_cast<int>(c.fluid.body_force.size()); ++d) lim.g[d] = c.fluid.body_force[d];
  lim.g_ramp = c.fluid.body_force_ramp;
  return lim;
}

template <int D>
HealthLimits health_limits(const Config& c, double velocity_scale, bool free_surface, const SphSystem<D>& sys,
                           const double* y0) {
  return health_limits<D>(c, velocity_scale, free_surface, health_sums<D>(c, sys, y0));
}

}  // namespace sphmol
