#pragma once
// A case built from a config and stepped a fixed number of times on a given number of threads: the
// state after the steps and the system's counters, for tests that compare two runs bit for bit.
#include <omp.h>

#include <cstddef>
#include <vector>

#include "sphmol/cases/case_module.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/time/integrator.hpp"

namespace test_support {

struct SteppedRun {
  std::vector<double> y;
  long evaluations = 0, symmetric = 0, rebuilds = 0;
};

// `setup(system)` runs on the built system before the integrator starts.
template <int D, class Setup>
SteppedRun run_steps(const sphmol::Config& c, int steps, int threads, Setup setup) {
  omp_set_num_threads(threads);
  auto sys = sphmol::make_case<D>(c)->build(c);
  setup(*sys);
  SteppedRun r;
  r.y = sys->initial_state();
  auto integ = sphmol::make_integrator(c.time);
  integ->initialize(*sys, 0.0, r.y.data());
  for (int s = 0; s < steps; ++s) integ->step_toward(c.time.t_end);
  r.evaluations = sys->rhs_evaluations();
  r.symmetric = sys->symmetric_evaluations();
  r.rebuilds = sys->pair_list().rebuilds();
  return r;
}

// How many entries of two states differ (compared as numbers).
inline std::size_t differing(const std::vector<double>& a, const std::vector<double>& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += a[i] != b[i] ? 1 : 0;
  return n;
}

}  // namespace test_support
