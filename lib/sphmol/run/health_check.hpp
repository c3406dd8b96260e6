#pragma once
// Blow-up detection after every accepted step: NaN/Inf in the state, density <= 0 in the latest RHS
// evaluation, or the CFL step
// collapsing below kCollapse times its initial value; then the physical bounds of the scene
// (run/health_limits.hpp): a speed above the scene's velocity scale or the sound speed, a density
// outside the EOS's weakly compressible range, kinetic energy beyond what the scene puts in. Throws
// BlowUp naming the time, the particle and the cause; keeps a copy of the last state that passed,
// for the run to write. A fluid particle beyond a face of the domain that is open to outflow
// (Domain::outflow) is not a blow-up: the check notes it (exits()), and the run takes it out between
// steps (run/outflow.hpp); beyond any other face of a non-periodic direction it has gone through a
// wall, which is. Particles already taken out (Kind::Out) are left out of every test and sum.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "sphmol/rhs/sph_system.hpp"
#include "sphmol/run/health_limits.hpp"
#include "sphmol/run/physical_bounds.hpp"
#include "sphmol/time/blow_up.hpp"
#include "sphmol/time/particle_split.hpp"

namespace sphmol {

template <int D>
class HealthCheck {
 public:
  static constexpr double kCollapse = 1e-6;

  HealthCheck(const SphSystem<D>& sys, const double* y0, double t0, HealthLimits limits = {})
      : sys_(sys), last_good_(y0, y0 + sys.size()), last_good_t_(t0), initial_cfl_(sys.stable_step()),
        bounds_(std::move(limits), t0) {
    bounds_.start(bounds_.sums(sys_.layout(), y0, inputs(t0, false), static_cast<long>(sys_.layout().n)));
  }

  void operator()(double t, const double* y, double /*h*/) {
    const Scan s = scan(t, y);
    exits_ = s.exits;
    if (!s.healthy) report(t, y);
    physical(t, y, s);
    const double cfl = sys_.stable_step();
    if (std::isfinite(initial_cfl_) && !(cfl >= kCollapse * initial_cfl_))
      throw BlowUp(t, -1, "step-size collapse: the CFL step fell from " + std::to_string(initial_cfl_) + " s to " +
                              std::to_string(cfl) + " s");
    last_good_.swap(candidate_);  // the copy scan() made; the previous good state is reused next time
    last_good_t_ = t;
  }

  // Whether a fluid particle not yet taken out was outside the domain in a non-periodic direction
  // after the latest step (run/outflow.hpp takes it out).
  bool exits() const { return exits_; }
  const std::vector<double>& last_good_state() const { return last_good_; }
  double last_good_time() const { return last_good_t_; }
  // Work done on the fluid by the body force since t0 (run/physical_bounds.hpp).
  double body_force_work() const { return bounds_.work(); }

 private:
  // The sums of the physical bounds (run/physical_bounds.hpp) are taken over fixed blocks of
  // kSumBlock particles and the block sums are added in block order, so the totals do not depend on
  // the thread count while the blocks are summed in parallel inside scan()'s region.
  static constexpr long kSumBlock = PhysicalBounds<D>::kMaxBlock;
  using Sums = PhysicalSums<D>;
  PhysicalInputs<D> inputs(double t, bool elastic) const {
    PhysicalInputs<D> in;
    in.V = bounds_.frame_velocity(t);
    in.mass = sys_.particles().mass.data();
    const auto& own = sys_.particles().rest_density;
    in.own = own.empty() ? nullptr : own.data();
    in.own_n = static_cast<long>(own.size());
    if (!sys_.retired().empty()) in.kind = sys_.particles().kind.data();
    if (elastic && bounds_.elastic()) {
      const auto& rho = sys_.density();  // state order, as the masses
      in.rho = rho.data();
      in.nrho = std::min(static_cast<long>(sys_.layout().n), static_cast<long>(rho.size()));
    }
    return in;
  }
  long sum_blocks() const { return (static_cast<long>(sys_.layout().n) + kSumBlock - 1) / kSumBlock; }
  struct Scan {
    bool healthy = true;
    bool exits = false;  // a fluid particle not taken out is outside the domain (non-periodic direction)
    double rho_lo = std::numeric_limits<double>::infinity(), rho_hi = -std::numeric_limits<double>::infinity();
    Sums sums;  // of the velocities and densities; meaningful only when healthy
  };

  // The scene's physical bounds (run/health_limits.hpp), after the state is known to be finite.
  void physical(double t, const double* y, const Scan& s) {
    const auto& L = sys_.layout();
    const long n = static_cast<long>(L.n);
    // From scan()'s block sums: the same for any thread count, and so the message.
    if (bounds_.too_fast(s.sums.vmax2))
      for (long i = 0; i < n; ++i) {
        double v2 = 0.0;
        for (int d = 0; d < D; ++d) v2 += y[L.velocity(d) + i] * y[L.velocity(d) + i];
        if (bounds_.too_fast(v2)) throw bounds_.speed_blow_up(t, i, v2);
      }
    if (bounds_.density_bounded()) {
      // Fluids of several rest densities (Particles::rest_density, state order): each particle against
      // its own rho0, read in state order; with one rho0 the extremes come from the scan.
      const auto& own = sys_.particles().rest_density;
      const double r0 = bounds_.limits().rho0;
      const auto rest = [&](long i) { return own.empty() ? r0 : own[static_cast<std::size_t>(i)]; };
      double lo = s.rho_lo / r0, hi = s.rho_hi / r0;  // of rho / rho0
      if (!own.empty()) {
        const auto& rho = sys_.density();
        const long nrho = std::min(n, static_cast<long>(rho.size()));
        lo = std::numeric_limits<double>::infinity();
        hi = -lo;
        for (long i = 0; i < nrho; ++i) {
          if (sys_.is_retired(static_cast<std::size_t>(i))) continue;
          lo = std::min(lo, rho[i] / rest(i));
          hi = std::max(hi, rho[i] / rest(i));
        }
      }
      if (bounds_.outside_density(hi) || bounds_.outside_density(lo)) {
        const auto& rs = sys_.density();  // state order, to name the particle
        for (std::size_t i = 0; i < L.n && i < rs.size(); ++i) {
          if (sys_.is_retired(i)) continue;
          const double ratio = rs[i] / rest(static_cast<long>(i));
          if (bounds_.outside_density(ratio)) throw bounds_.density_blow_up(t, static_cast<long>(i), ratio);
        }
      }
    }
    bounds_.energy(t, s.sums);
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
    // Particles taken out are skipped (their kinds in state and in workspace order).
    const Kind* const kind = sys_.particles().kind.data();
    const Kind* const wkind = sys_.workspace_kind().data();
    candidate_.resize(static_cast<std::size_t>(size));
    double* const keep = candidate_.data();
    bool bad = false;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    std::int64_t rho_ok = 1;
    const PhysicalInputs<D> in = inputs(t, true);
    const long nb = sum_blocks();
    parts_.resize(static_cast<std::size_t>(nb));
    Sums* const part = parts_.data();
    bool exits = false;
#pragma omp parallel reduction(|| : bad, exits)
    {
      // Every test is an AND of comparisons without branches (into an integer as wide as a double,
      // which GCC vectorises), so that the loops vectorise: a value is finite when |v| <= the
      // largest double (false for NaN and Inf).
      constexpr double big = std::numeric_limits<double>::max();
      std::int64_t ok = 1, inside = 1;
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
          // A closed face: crossing it fails the check; an outflow face: noted (exits).
          const bool closed_lo = !open && !dom.outflow[d][0], closed_hi = !open && !dom.outflow[d][1];
          const double xlo = dom.lo[d], xhi = dom.hi[d];
          for (long i = i0; i < i1; ++i) {
            const double xi = x[i], vi = v[i];
            const bool live = kind[i] != Kind::Out;
            ok &= static_cast<std::int64_t>((std::fabs(xi) <= big) & (std::fabs(vi) <= big) &
                                            !(live & ((closed_lo & (xi < xlo)) | (closed_hi & (xi > xhi)))));
            inside &= static_cast<std::int64_t>(open | ((xi >= xlo) & (xi <= xhi)) | !live);
            kx[i] = xi;
            kv[i] = vi;
          }
        }
        part[b] = bounds_.sums(L, y, in, i0, i1);
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
        const bool live = wkind[i] != Kind::Out;
        rho_ok &= static_cast<std::int64_t>((r > 0.0) | !live);
        lo = std::min(lo, live ? r : std::numeric_limits<double>::infinity());
        hi = std::max(hi, live ? r : -std::numeric_limits<double>::infinity());
      }
      bad = ok == 0;
      exits = inside == 0;
    }
    Scan s{!bad && rho_ok != 0, exits, lo, hi, {}};
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
        if (!sys_.is_retired(i) && dom.beyond_closed_face(d, x[i]))
          throw BlowUp(t, static_cast<long>(i), "particle left the domain in direction " + std::to_string(d) +
                                                    " through a face closed to outflow (x = " + std::to_string(x[i]) +
                                                    ", domain [" + std::to_string(dom.lo[d]) + ", " + std::to_string(dom.hi[d]) + "])");
      }
    }
    for (std::size_t k = L.velocities_end(); k < L.size(); ++k)
      if (!std::isfinite(y[k])) throw BlowUp(t, static_cast<long>((k - L.velocities_end()) % n), "NaN/Inf in a state field");
    const auto& rho = sys_.density();
    for (std::size_t i = 0; i < n && i < rho.size(); ++i)
      if (!(rho[i] > 0.0) && !sys_.is_retired(i)) throw BlowUp(t, static_cast<long>(i), "density <= 0 (rho = " + std::to_string(rho[i]) + ")");
  }

  const SphSystem<D>& sys_;
  std::vector<double> last_good_, candidate_;
  std::vector<Sums> parts_;  // scan()'s block sums
  double last_good_t_;
  double initial_cfl_;
  bool exits_ = false;
  PhysicalBounds<D> bounds_;
};

}  // namespace sphmol
