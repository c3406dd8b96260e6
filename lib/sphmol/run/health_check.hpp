#pragma once
// Blow-up detection after every accepted step: NaN/Inf in the state, a fluid particle outside the
// domain in a non-periodic direction, density <= 0 in the latest RHS evaluation, or the CFL step
// collapsing below kCollapse times its initial value. Throws BlowUp naming the time, the particle
// and the cause; keeps a copy of the last state that passed, for the run to write.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "sphmol/rhs/sph_system.hpp"
#include "sphmol/time/blow_up.hpp"
#include "sphmol/time/particle_split.hpp"

namespace sphmol {

template <int D>
class HealthCheck {
 public:
  static constexpr double kCollapse = 1e-6;

  HealthCheck(const SphSystem<D>& sys, const double* y0, double t0)
      : sys_(sys), last_good_(y0, y0 + sys.size()), last_good_t_(t0), initial_cfl_(sys.stable_step()) {}

  void operator()(double t, const double* y, double /*h*/) {
    if (!healthy(y)) report(t, y);
    const double cfl = sys_.stable_step();
    if (std::isfinite(initial_cfl_) && !(cfl >= kCollapse * initial_cfl_))
      throw BlowUp(t, -1, "step-size collapse: the CFL step fell from " + std::to_string(initial_cfl_) + " s to " +
                              std::to_string(cfl) + " s");
    const std::size_t size = sys_.layout().size();
    last_good_.resize(size);
    double* const keep = last_good_.data();
#pragma omp parallel
    for_each_by_particle(0, size, sys_.layout().n, [&](std::size_t k) { keep[k] = y[k]; });
    last_good_t_ = t;
  }

  const std::vector<double>& last_good_state() const { return last_good_; }
  double last_good_time() const { return last_good_t_; }

 private:
  // The per-particle tests of report() as one parallel pass (run after every step); report() then
  // finds the first failure in its order, so the message does not depend on the thread count.
  bool healthy(const double* y) const {
    const auto& L = sys_.layout();
    const auto& dom = sys_.domain();
    const long n = static_cast<long>(L.n), size = static_cast<long>(L.size()), ve = static_cast<long>(L.velocities_end());
    // The density in workspace order: the test is the same for every particle, and density() would
    // permute it serially after every step. Fluid entries come first in either order.
    const auto& rho = sys_.workspace_density();
    const long nrho = std::min(n, static_cast<long>(rho.size()));
    bool bad = false;
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
#pragma omp for schedule(static) nowait
      for (long i = 0; i < nrho; ++i) bad |= !(rho[i] > 0.0);
    }
    return !bad;
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
  std::vector<double> last_good_;
  double last_good_t_;
  double initial_cfl_;
};

}  // namespace sphmol
