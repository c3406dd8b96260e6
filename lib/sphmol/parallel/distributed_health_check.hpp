#pragma once
// Blow-up detection after every accepted step of a run over ranks: the numerical tests of the
// serial check (run/health_check.hpp) on each rank's own particles, NaN/Inf in the state, a fluid
// particle outside the domain in a non-periodic direction, density <= 0 in the latest evaluation,
// and the CFL step collapsing; one verdict for all ranks, so every rank throws the same BlowUp (the
// first failing rank's first failure, naming the particle by its global id) and none is left
// waiting in a collective. The physical bounds of run/health_limits.hpp (speeds, densities and
// energy against the scene's scales) are not checked over ranks. The same all-gather carries each
// rank's pending signal (run/signals.hpp), so that the ranks agree at every step on whether to stop
// (the largest signal of all) at no extra collective.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/distributed_system.hpp"
#include "sphmol/run/health_check.hpp"
#include "sphmol/time/blow_up.hpp"

namespace sphmol::parallel {

template <int D>
class DistributedHealthCheck {
 public:
  DistributedHealthCheck(const Communicator& comm, const DistributedSystem<D>& sys, double t0)
      : comm_(comm), sys_(sys), last_good_t_(t0) {}

  // `signal`: this rank's pending signal (0: none); returns the largest of all ranks'.
  int operator()(double t, const double* y, int signal) {
    long particle = -1;
    const std::string cause = first_failure(y, particle);
    const std::vector<Verdict> verdicts = comm_.all_gather(Verdict{!cause.empty(), signal});
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
    // Both the same on every rank (reductions).
    const double cfl = sys_.stable_step(), initial = sys_.first_stable_step();
    if (std::isfinite(initial) && !(cfl >= HealthCheck<D>::kCollapse * initial))
      throw BlowUp(t, -1, "step-size collapse: the CFL step fell from " + std::to_string(initial) + " s to " +
                              std::to_string(cfl) + " s");
    last_good_t_ = t;
    int largest = 0;
    for (const Verdict& v : verdicts) largest = std::max(largest, v.signal);
    return largest;
  }

  double last_good_time() const { return last_good_t_; }

 private:
  struct Verdict {
    int failed;  // 0 or 1
    int signal;
  };

  // This rank's first failure in the serial check's order ("" when none), and its particle.
  std::string first_failure(const double* y, long& particle) const {
    const auto& L = sys_.layout();
    const auto& dom = sys_.domain();
    const auto& gid = sys_.gid();
    for (int d = 0; d < D; ++d) {
      const double* x = y + L.position(d);
      const double* v = y + L.velocity(d);
      for (std::size_t i = 0; i < L.n; ++i) {
        particle = static_cast<long>(gid[i]);
        if (!std::isfinite(x[i]) || !std::isfinite(v[i]))
          return std::string("NaN/Inf in the ") + (std::isfinite(x[i]) ? "velocity" : "position") + " (component " +
                 std::to_string(d) + ")";
        if (!dom.periodic[d] && (x[i] < dom.lo[d] || x[i] > dom.hi[d]))
          return "particle left the domain in direction " + std::to_string(d) + " (x = " + std::to_string(x[i]) +
                 ", domain [" + std::to_string(dom.lo[d]) + ", " + std::to_string(dom.hi[d]) + "])";
      }
    }
    for (std::size_t k = L.velocities_end(); k < L.size(); ++k)
      if (!std::isfinite(y[k])) {
        const std::size_t i = (k - L.velocities_end()) % std::max<std::size_t>(L.n, 1);
        particle = i < gid.size() ? static_cast<long>(gid[i]) : -1;
        return "NaN/Inf in a state field";
      }
    for (std::size_t i = 0; i < L.n; ++i) {
      const double rho = sys_.owned_density(i);
      particle = static_cast<long>(gid[i]);
      if (!(rho > 0.0)) return "density <= 0 (rho = " + std::to_string(rho) + ")";
    }
    particle = -1;
    return "";
  }

  Communicator comm_;
  const DistributedSystem<D>& sys_;
  double last_good_t_;
};

}  // namespace sphmol::parallel
