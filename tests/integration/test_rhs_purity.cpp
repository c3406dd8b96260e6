// The right-hand side f(t, y) is a function of its arguments only: evaluating it at the same (t, y)
// twice, with evaluations at other states in between, gives bit-identical results. A Runge-Kutta
// method evaluates f at stage states in any order (Verner 8(5)6's seventh stage, c = 1/15, follows
// its sixth, c = 1); any value kept from the previous evaluation makes f depend on that order and
// turns the scheme into a different, possibly unstable, one.
#include <catch2/catch.hpp>

#include <cmath>
#include <omp.h>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/run/case_registry.hpp"
#include "sphmol/time/integrator.hpp"

using namespace sphmol;

namespace {

struct Mismatch {
  std::size_t count = 0;
  double worst = 0.0;  // largest |difference| relative to the largest |f|
};

Mismatch compare(const std::vector<double>& a, const std::vector<double>& b) {
  Mismatch m;
  double scale = 0.0;
  for (double v : a) scale = std::max(scale, std::abs(v));
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) {
      ++m.count;
      m.worst = std::max(m.worst, std::abs(a[i] - b[i]) / (scale > 0.0 ? scale : 1.0));
    }
  return m;
}

// f at y, then at a state a "stage" away (y + dt * f(y) * factor), then at y again.
Mismatch repeat_after_other_state(const std::string& file, const std::vector<std::string>& overrides, int steps,
                                  double factor) {
  omp_set_num_threads(1);
  const Config c = load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/" + file, overrides);
  auto sys = case_registry().at(c.case_name).d2()->build(c);
  std::vector<double> y = sys->initial_state();
  auto integ = make_integrator(c.time);
  integ->initialize(*sys, 0.0, y.data());
  double t = 0.0;
  for (int s = 0; s < steps; ++s) t = integ->step_toward(c.time.t_end);
  const double dt = sys->stable_step();
  std::vector<double> f1(y.size()), f2(y.size()), g(y.size()), z(y.size());
  sys->rhs(t, y.data(), f1.data());
  for (std::size_t i = 0; i < y.size(); ++i) z[i] = y[i] + factor * dt * f1[i];
  sys->rhs(t + factor * dt, z.data(), g.data());
  sys->rhs(t, y.data(), f2.data());
  return compare(f1, f2);
}

}  // namespace

TEST_CASE("rhs purity: f(t, y) is bit-identical when evaluated again after another state (channels)",
          "[integration][rhs_purity]") {
  for (const char* file : {"poiseuille.yaml", "couette.yaml"}) {
    for (double factor : {1.0, -1.0, 4.0}) {
      const Mismatch m = repeat_after_other_state(file, {"time.t_end=1.0"}, 20, factor);
      INFO(file << " other state at " << factor << " dt: " << m.count << " entries differ, worst " << m.worst);
      CHECK(m.count == 0);
    }
  }
}
