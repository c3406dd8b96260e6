#pragma once
// Blow-up detection after every accepted step of a run over ranks: the tests of the serial check
// (run/health_check.hpp) on each rank's own particles, in its order. First the numerical ones, NaN/Inf
// in the state, a fluid particle beyond a face of the domain closed to outflow, density <= 0 in
// the latest evaluation; then the physical bounds of the scene (run/health_limits.hpp: speed,
// density range, mechanical energy budget, run/physical_bounds.hpp), and the CFL step collapsing.
// One verdict for all ranks, so every rank throws the same BlowUp and none is left waiting in a
// collective: a numerical failure is the first failing rank's first one; a speed or density bound
// names the particle of smallest global id that exceeds it (the serial check's particle); the
// energy bound tests the sum of the ranks' sums, added in rank order on every rank (the serial sums
// up to round-off). One all-gather per step carries each rank's verdict, its sums and its first
// particles past the bounds, and its pending signal (run/signals.hpp), so that the ranks also agree
// at every step on whether to stop (the largest signal of all); the stable step's collapse is
// tested on the step size the evaluation has already reduced. A failure costs three more
// all-gathers for the failing rank's message. The last state that passed stays on each rank (its
// own particles), for the run to gather and write.
// A fluid particle beyond a face open to outflow is not a blow-up: as the serial check, this one
// notes it (exits()), and the run takes it out between steps (run/outflow.hpp). Each rank's verdict
// carries the count of its own leavers, so every rank learns from the same all-gather that some rank
// has them; only then (a step with exits, once every test has passed) does a further all-gather
// bring their global ids to every rank (leavers(), ascending), so that all ranks take the same
// particles out at the same step. Particles already taken out (Kind::Out) are left out of every test
// and sum, as in the serial check.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/distributed_system.hpp"
#include "sphmol/parallel/piece_collectives.hpp"
#include "sphmol/run/health_check.hpp"
#include "sphmol/run/health_limits.hpp"
#include "sphmol/run/physical_bounds.hpp"
#include "sphmol/time/blow_up.hpp"

namespace sphmol::parallel {

template <int D>
class DistributedHealthCheck {
 public:
  // `y_local`: this rank's part of the state at t0. Collective: the physical bounds' sums at t0 (for
  // the body force's power there) from each rank's own particles, added in rank order as at every
  // check; the particles taken out at a restart's start are massless.
  DistributedHealthCheck(const Communicator& comm, const DistributedSystem<D>& sys, const std::vector<double>& y_local,
                         double t0, HealthLimits limits)
      : comm_(comm), sys_(sys), last_good_(y_local), last_good_t_(t0), bounds_(std::move(limits), t0) {
    const auto& L = sys_.layout();
    const long n = static_cast<long>(L.n);
    PhysicalInputs<D> in;
    in.V = bounds_.frame_velocity(t0);
    in.mass = sys_.owned().mass.data();
    in.kind = sys_.owned().kind.data();
    PhysicalSums<D> start;
    for (const PhysicalSums<D>& s : comm_.all_gather(bounds_.sums(L, y_local.data(), in, n))) start.add(s);
    bounds_.start(start);
  }
  // The elastic energy of the fluid at the system's latest evaluation (the first one, for the
  // limits' budget): exact over the ranks, the serial run's sum to the bit (run/health_limits.hpp).
  static double elastic_energy(const Communicator& comm, const DistributedSystem<D>& sys, const HealthLimits::Elastic& el) {
    const std::size_t n = sys.layout().n;
    std::vector<double> rho(n);
    for (std::size_t o = 0; o < n; ++o) rho[o] = sys.owned_density(o);
    return elastic_energy_total(el, sys.owned(), n, rho, piece_collectives(comm));
  }

  // `signal`: this rank's pending signal (0: none); returns the largest of all ranks'.
  int operator()(double t, const double* y, int signal) {
    long particle = -1;
    gather_density();
    int exits = 0;
    const std::string cause = any_numerical_failure(y, exits) ? first_failure(y, particle) : std::string();
    Verdict mine{!cause.empty(), signal, exits};
    if (cause.empty()) physical_sums(t, y, mine);
    const std::vector<Verdict> verdicts = comm_.all_gather(mine);
    for (std::size_t r = 0; r < verdicts.size(); ++r) {
      if (!verdicts[r].failed) continue;
      // The failing rank's message, on every rank.
      const std::vector<long> particles = comm_.all_gather(particle);
      const std::vector<int> lengths = comm_.all_gather(static_cast<int>(cause.size()));
      const std::vector<char> text = comm_.all_gather_v(std::vector<char>(cause.begin(), cause.end()));
      std::size_t at = 0;
      for (std::size_t q = 0; q < r; ++q) at += static_cast<std::size_t>(lengths[q]);
      throw BlowUp(t, particles[r], std::string(text.begin() + static_cast<long>(at), text.begin() + static_cast<long>(at) + lengths[r]));
    }
    physical(t, verdicts);
    // Both the same on every rank (reductions).
    const double cfl = sys_.stable_step(), initial = sys_.first_stable_step();
    if (std::isfinite(initial) && !(cfl >= HealthCheck<D>::kCollapse * initial))
      throw BlowUp(t, -1, "step-size collapse: the CFL step fell from " + std::to_string(initial) + " s to " +
                              std::to_string(cfl) + " s");
    last_good_.swap(candidate_);  // the copy the tests made; the previous good state is reused next time
    last_good_t_ = t;
    int largest = 0;
    bool any_exit = false;
    for (const Verdict& v : verdicts) {
      largest = std::max(largest, v.signal);
      any_exit = any_exit || v.exits > 0;
    }
    leavers_.clear();
    leaver_masses_.clear();
    // Decided alike on every rank (from the verdicts): the one collective more, in a step with exits.
    if (any_exit) gather_leavers(y, mine.exits);
    return largest;
  }

  // Whether a fluid particle not yet taken out was outside the domain after the latest step (on some
  // rank; the same on every rank), and the global ids of all of them, ascending, on every rank.
  bool exits() const { return !leavers_.empty(); }
  const std::vector<std::size_t>& leavers() const { return leavers_; }
  // Their masses, in the same order (from their owners: no rank needs the whole scene's masses).
  const std::vector<double>& leaver_masses() const { return leaver_masses_; }

  double last_good_time() const { return last_good_t_; }
  // This rank's part of the last state that passed (its layout that of the state when it passed).
  const std::vector<double>& last_good_state() const { return last_good_; }
  // After the particles moved between ranks at the last good state (a repartition between steps):
  // that state in the new share.
  void moved(const std::vector<double>& y) { last_good_ = y; }
  double body_force_work() const { return bounds_.work(); }

 private:
  struct Verdict {
    int failed;  // 0 or 1
    int signal;
    int exits;   // fluid particles of this rank outside the domain, not taken out yet
    // The physical bounds' sums over this rank's fluid particles, and the smallest global id past
    // the speed and the density bound (-1: none) with its speed squared and its rho / rho0.
    PhysicalSums<D> sums{};
    long fast = -1;
    double fast_v2 = 0.0;
    long dense = -1;
    double dense_ratio = 0.0;
  };

  // The owned fluid's densities of the latest evaluation (DistributedSystem::owned_density), gathered
  // from the local system's rows once per step.
  void gather_density() {
    const std::size_t n = sys_.layout().n;
    rho_.resize(n);
    if (n == 0) return;
    const auto& rows = sys_.owned_rows();
    const std::vector<double>& local = sys_.local_system().density();
    for (std::size_t o = 0; o < n; ++o) rho_[o] = local[rows[o]];
  }

  // Whether any of first_failure()'s tests fails, with the same comparisons written without an early
  // exit or a store per particle, so that the loops vectorise; the failure itself is looked for only
  // then. The same loops note whether a live fluid particle is outside the domain (beyond a face open
  // to outflow when no test fails), and `exits` counts those then, and copy y into candidate_, the
  // last good state once every test has passed (as the serial check's scan): y is read once per
  // step, not again for the copy.
  bool any_numerical_failure(const double* y, int& exits) {
    const auto& L = sys_.layout();
    const auto& dom = sys_.domain();
    const Kind* const kind = sys_.owned().kind.data();  // owned fluid first: index o of the state
    constexpr double big = std::numeric_limits<double>::max();
    candidate_.resize(L.size());
    double* const keep = candidate_.data();
    int bad = 0, outside = 0;
    for (int d = 0; d < D; ++d) {
      const double* x = y + L.position(d);
      const double* v = y + L.velocity(d);
      double* kx = keep + L.position(d);
      double* kv = keep + L.velocity(d);
      const bool open = dom.periodic[d];
      // A closed face: crossing it fails the check; an outflow face: noted (exits).
      const bool closed_lo = !open && !dom.outflow[d][0], closed_hi = !open && !dom.outflow[d][1];
      const double xlo = dom.lo[d], xhi = dom.hi[d];
      // & and | rather than && and ||: no branch per particle.
      for (std::size_t i = 0; i < L.n; ++i) {
        const double xi = x[i], vi = v[i];
        const bool live = kind[i] != Kind::Out;
        kx[i] = xi;
        kv[i] = vi;
        bad |= static_cast<int>((!((std::abs(xi) <= big) & (std::abs(vi) <= big))) |
                                (live & ((closed_lo & (xi < xlo)) | (closed_hi & (xi > xhi)))));
        outside |= static_cast<int>(live & (!open) & ((xi < xlo) | (xi > xhi)));
      }
    }
    for (std::size_t k = L.velocities_end(); k < L.size(); ++k) {
      const double yk = y[k];
      keep[k] = yk;
      bad |= static_cast<int>(!(std::abs(yk) <= big));
    }
    for (std::size_t i = 0; i < rho_.size(); ++i) bad |= static_cast<int>(!(rho_[i] > 0.0) & (kind[i] != Kind::Out));
    exits = bad == 0 && outside != 0 ? static_cast<int>(leaving(y).size()) : 0;
    return bad != 0;
  }

  // This rank's live fluid particles outside the domain (owned state indices, ascending), as
  // run/outflow.hpp's fluid_outside_domain finds them in the whole state.
  std::vector<std::size_t> leaving(const double* y) const {
    const auto& L = sys_.layout();
    const auto& dom = sys_.domain();
    const auto& kind = sys_.owned().kind;
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < L.n; ++i) {
      if (kind[i] == Kind::Out) continue;
      for (int d = 0; d < D; ++d)
        if (dom.outside(d, y[L.position(d) + i])) {
          out.push_back(i);
          break;
        }
    }
    return out;
  }

  // Collective: every rank's leavers by global id into leavers_, ascending, on every rank.
  void gather_leavers(const double* y, int mine) {
    struct Leaver {
      std::uint64_t id;
      double mass;
    };
    std::vector<Leaver> own;
    if (mine > 0)
      for (const std::size_t o : leaving(y)) own.push_back({sys_.gid()[o], sys_.owned().mass[o]});
    std::vector<Leaver> all = comm_.all_gather_v(own);
    std::sort(all.begin(), all.end(), [](const Leaver& a, const Leaver& b) { return a.id < b.id; });
    leavers_.resize(all.size());
    leaver_masses_.resize(all.size());
    for (std::size_t k = 0; k < all.size(); ++k) {
      leavers_[k] = static_cast<std::size_t>(all[k].id);
      leaver_masses_[k] = all[k].mass;
    }
  }

  // This rank's part of the physical bounds, after its state has passed the numerical tests.
  void physical_sums(double t, const double* y, Verdict& v) {
    const auto& L = sys_.layout();
    const auto& gid = sys_.gid();
    const long n = static_cast<long>(L.n);
    const auto& own = sys_.owned().rest_density;
    PhysicalInputs<D> in;
    in.V = bounds_.frame_velocity(t);
    in.mass = sys_.owned().mass.data();
    const Kind* const kind = sys_.owned().kind.data();
    if (std::any_of(kind, kind + n, [](Kind k) { return k == Kind::Out; })) in.kind = kind;  // massless
    in.own = own.empty() ? nullptr : own.data();
    in.own_n = static_cast<long>(own.size());
    if (bounds_.elastic()) {
      in.rho = rho_.data();
      in.nrho = n;
    }
    v.sums = bounds_.sums(L, y, in, n);
    if (bounds_.too_fast(v.sums.vmax2))
      for (long o = 0; o < n; ++o) {
        double v2 = 0.0;
        for (int d = 0; d < D; ++d) v2 += y[L.velocity(d) + o] * y[L.velocity(d) + o];
        const long id = static_cast<long>(gid[static_cast<std::size_t>(o)]);
        if (bounds_.too_fast(v2) && (v.fast < 0 || id < v.fast)) {
          v.fast = id;
          v.fast_v2 = v2;
        }
      }
    if (bounds_.density_bounded()) {
      // With one rest density the extremes first (as the serial check's scan): the particles are
      // looked at one by one only when some of them is past the bound.
      const double r0 = bounds_.limits().rho0;
      // Particles taken out are skipped.
      bool past = !own.empty();
      if (!past && n > 0) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (long o = 0; o < n; ++o) {
          const bool live = kind[o] != Kind::Out;
          lo = std::min(lo, live ? rho_[static_cast<std::size_t>(o)] : std::numeric_limits<double>::infinity());
          hi = std::max(hi, live ? rho_[static_cast<std::size_t>(o)] : -std::numeric_limits<double>::infinity());
        }
        past = bounds_.outside_density(lo / r0) || bounds_.outside_density(hi / r0);
      }
      for (long o = 0; o < n && past; ++o) {
        const auto k = static_cast<std::size_t>(o);
        if (kind[k] == Kind::Out) continue;
        const double ratio = rho_[k] / (own.empty() ? r0 : own[k]);
        const long id = static_cast<long>(gid[k]);
        if (bounds_.outside_density(ratio) && (v.dense < 0 || id < v.dense)) {
          v.dense = id;
          v.dense_ratio = ratio;
        }
      }
    }
  }

  // The serial check's order on every rank's verdict: speed, density, energy (its sums added in rank order).
  void physical(double t, const std::vector<Verdict>& verdicts) {
    const Verdict* fast = nullptr;
    const Verdict* dense = nullptr;
    PhysicalSums<D> total;
    for (const Verdict& v : verdicts) {
      if (v.fast >= 0 && (!fast || v.fast < fast->fast)) fast = &v;
      if (v.dense >= 0 && (!dense || v.dense < dense->dense)) dense = &v;
      total.add(v.sums);
    }
    if (fast) throw bounds_.speed_blow_up(t, fast->fast, fast->fast_v2);
    if (dense) throw bounds_.density_blow_up(t, dense->dense, dense->dense_ratio);
    bounds_.energy(t, total);
  }

  // This rank's first failure in the serial check's order ("" when none), and its particle.
  std::string first_failure(const double* y, long& particle) const {
    const auto& L = sys_.layout();
    const auto& dom = sys_.domain();
    const auto& gid = sys_.gid();
    const auto& kind = sys_.owned().kind;
    for (int d = 0; d < D; ++d) {
      const double* x = y + L.position(d);
      const double* v = y + L.velocity(d);
      for (std::size_t i = 0; i < L.n; ++i) {
        particle = static_cast<long>(gid[i]);
        if (!std::isfinite(x[i]) || !std::isfinite(v[i]))
          return std::string("NaN/Inf in the ") + (std::isfinite(x[i]) ? "velocity" : "position") + " (component " +
                 std::to_string(d) + ")";
        // Beyond a face open to outflow the run takes the particle out (exits()).
        if (kind[i] != Kind::Out && dom.beyond_closed_face(d, x[i]))
          return "particle left the domain in direction " + std::to_string(d) + " through a face closed to outflow (x = " +
                 std::to_string(x[i]) + ", domain [" + std::to_string(dom.lo[d]) + ", " + std::to_string(dom.hi[d]) + "])";
      }
    }
    for (std::size_t k = L.velocities_end(); k < L.size(); ++k)
      if (!std::isfinite(y[k])) {
        const std::size_t i = (k - L.velocities_end()) % std::max<std::size_t>(L.n, 1);
        particle = i < gid.size() ? static_cast<long>(gid[i]) : -1;
        return "NaN/Inf in a state field";
      }
    for (std::size_t i = 0; i < L.n; ++i) {
      if (kind[i] == Kind::Out) continue;
      const double rho = sys_.owned_density(i);
      particle = static_cast<long>(gid[i]);
      if (!(rho > 0.0)) return "density <= 0 (rho = " + std::to_string(rho) + ")";
    }
    particle = -1;
    return "";
  }

  Communicator comm_;
  const DistributedSystem<D>& sys_;
  std::vector<double> last_good_, candidate_;  // candidate_: the copy of the step being tested
  double last_good_t_;
  PhysicalBounds<D> bounds_;
  std::vector<double> rho_;  // the owned fluid's densities of the latest evaluation, in state order
  std::vector<std::size_t> leavers_;  // the latest step's, by global id (every rank's, ascending)
  std::vector<double> leaver_masses_;
};

}  // namespace sphmol::parallel
