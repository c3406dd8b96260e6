// sph-bench, end to end: the dam break (verification/dam_break.yaml: 20,000 fluid + 1,002
// wall particles, Wendland C2, h = 1.414 dp, continuity + delta-SPH, artificial viscosity, dynamic
// walls), leapfrog with one RHS evaluation per step. "us/particle-step" = wall time / (steps x all
// particles), the number compared with DualSPHysics 5.4 on the same dam break (0.67 us on 1 thread, 0.37 on 2).
//   sph-bench --benchmark_filter=DamBreakStep   single steps on 1 and 2 threads
//   sph-bench --benchmark_filter=DamBreakRun    whole runs, 1 and 2 threads alternating
//   sph-bench --benchmark_filter=DamBreakContention   1 thread, 2 threads, and 2 threads beside a
//                                                process that keeps one core busy, alternating
// sph-bench, like sph-mol, runs with idle threads spinning GOMP_SPINCOUNT = 1,000 iterations unless
// OMP_WAIT_POLICY or GOMP_SPINCOUNT is set (run/openmp_wait_policy.hpp); the label names the policy.
#include <benchmark/benchmark.h>
#include <omp.h>
#include <sched.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>

#include "sphmol/config/config.hpp"
#include "sphmol/rhs/sph_system.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/time/integrator.hpp"

namespace {

// The dam break of `config`, built and started at t = 0 with its integrator.
struct DamBreak {
  std::unique_ptr<sphmol::SphSystem<2>> sys;
  std::vector<double> y;  // the state the integrator advances in place (declared first: outlives it)
  std::unique_ptr<sphmol::Integrator> integrator;
  explicit DamBreak(const sphmol::Config& config)
      : sys(sphmol::make_case<2>(config)->build(config)),
        y(sys->initial_state()),
        integrator(sphmol::make_integrator(config.time)) {
    integrator->initialize(*sys, 0.0, y.data());
  }
};

std::string dam_break_yaml() { return std::string(SPHMOL_SOURCE_DIR) + "/verification/dam_break.yaml"; }

// One benchmark iteration is one time step. Argument: threads. The column first collapses for 200
// steps (leaving the state at rest would understate the neighbour-list rebuilds).
void DamBreakStep(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  omp_set_num_threads(threads);
  DamBreak run(sphmol::load_config(dam_break_yaml()));
  const double never = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 200; ++k) run.integrator->step_toward(never);
  for (auto _ : state) {
    run.integrator->step_toward(never);
    benchmark::DoNotOptimize(run.y.data());
  }
  const double particles = static_cast<double>(run.sys->particles().size());
  state.counters["us/particle-step"] = benchmark::Counter(
      particles * 1e-6, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["particles"] = particles;
  omp_set_num_threads(1);
}
BENCHMARK(DamBreakStep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

// Symmetric pair evaluation against full rows (rhs/fused_pair_pass.hpp) in one run: after
// `after_steps` steps (200: the collapse under way; 6000: t = 0.19 s, the surge along the floor, the
// particles' order mixed), blocks of 20 steps alternate between the two (the states agree bit for
// bit, so both see the same flow). Reports µs per particle-step of each and full / symmetric.
void DamBreakSymmetric(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  omp_set_num_threads(threads);
  DamBreak run(sphmol::load_config(dam_break_yaml()));
  const double never = std::numeric_limits<double>::infinity();
  for (long k = 0; k < state.range(1); ++k) run.integrator->step_toward(never);
  std::array<double, 2> wall{};  // [symmetric]
  std::array<long, 2> steps{};
  for (auto _ : state) {
    for (int k = 0; k < 40; ++k) {
      const int sym = k % 2;
      run.sys->set_symmetric_pairs(sym == 1);
      const double start = omp_get_wtime();
      for (int s = 0; s < 20; ++s) run.integrator->step_toward(never);
      wall[static_cast<std::size_t>(sym)] += omp_get_wtime() - start;
      steps[static_cast<std::size_t>(sym)] += 20;
    }
  }
  run.sys->set_symmetric_pairs(true);
  const double particles = static_cast<double>(run.sys->particles().size());
  auto us = [&](int k) { return 1e6 * wall[static_cast<std::size_t>(k)] / (static_cast<double>(steps[static_cast<std::size_t>(k)]) * particles); };
  state.counters["us_full"] = us(0);
  state.counters["us_symmetric"] = us(1);
  state.counters["full_vs_symmetric"] = us(0) / us(1);
  omp_set_num_threads(1);
}
BENCHMARK(DamBreakSymmetric)->Args({1, 200})->Args({2, 200})->Args({1, 6000})->Args({2, 6000})->ArgNames({"threads", "after_steps"})->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

// The run of dam_break.yaml from t = 0 to t_end_ms / 1000 s (1000: the whole run) once, in blocks
// of `block` steps that alternate between 1 and 2 threads. Results do not depend on the thread count
// (tests/integration/test_determinism.cpp), so this is the shipped run; and since both thread counts
// sample every phase of it within a few hundred milliseconds of each other, the 2-vs-1 ratio is free
// of the slow drift in machine speed that made separate 1- and 2-thread runs on this VM scatter by
// 30 %.
// Counters: us/particle-step on each thread count and their ratio, over the whole run and over
// t < t_end / 2 and t >= t_end / 2 apart; the ratio for the search, the rest of the RHS and the rest
// of the step; and how the fused pair rows split between the two threads.
void DamBreakRun(benchmark::State& state) {
  const long block = state.range(0);
  const double t_end = 1e-3 * static_cast<double>(state.range(1));
  const auto config = sphmol::load_config(dam_break_yaml(), {"time.t_end=" + std::to_string(t_end)});
  std::array<std::array<double, 2>, 2> wall{};   // [half][threads - 1]
  std::array<std::array<long, 2>, 2> steps{};
  std::array<double, 2> rhs{}, search{};  // [threads - 1]: the parts of the wall time in the RHS, in the search
  double rows_1 = 0.0;                    // 1 thread: seconds on fused pair rows
  std::array<double, 2> rows_2{};         // 2 threads: each thread's seconds on them
  double particles = 0.0;
  for (auto _ : state) {
    DamBreak run(config);
    auto& sys = run.sys;
    auto& integrator = run.integrator;
    particles = static_cast<double>(sys->particles().size());
    double t = 0.0;
    for (long k = 0; t < t_end; ++k) {
      const int threads = 1 + static_cast<int>(k % 2);
      const int half = t < 0.5 * t_end ? 0 : 1;
      omp_set_num_threads(threads);
      const double start = omp_get_wtime(), rhs0 = sys->rhs_seconds(), search0 = sys->search_seconds();
      const std::vector<double> rows0 = sys->pair_thread_seconds();
      long n = 0;
      for (; n < block && t < t_end; ++n) t = integrator->step_toward(t_end);
      const std::vector<double>& rows = sys->pair_thread_seconds();
      for (std::size_t q = 0; q < rows.size() && q < 2; ++q) {
        const double spent = rows[q] - (q < rows0.size() ? rows0[q] : 0.0);
        if (threads == 1) rows_1 += spent;
        else rows_2[q] += spent;
      }
      wall[half][threads - 1] += omp_get_wtime() - start;
      rhs[threads - 1] += sys->rhs_seconds() - rhs0;
      search[threads - 1] += sys->search_seconds() - search0;
      steps[half][threads - 1] += n;
    }
    benchmark::DoNotOptimize(run.y.data());
  }
  omp_set_num_threads(1);
  const auto us = [&](double w, long s) { return s > 0 ? 1e6 * w / (static_cast<double>(s) * particles) : 0.0; };
  const auto both = [&](int th) { return us(wall[0][th] + wall[1][th], steps[0][th] + steps[1][th]); };
  state.counters["us_1thread"] = both(0);
  state.counters["us_2threads"] = both(1);
  state.counters["2vs1"] = both(0) / both(1);
  // The whole run's steps on one thread count alone, from its rate (set-up, health checks and output
  // not included).
  const double all_steps = static_cast<double>(steps[0][0] + steps[0][1] + steps[1][0] + steps[1][1]);
  state.counters["steps_s_1thread"] = 1e-6 * both(0) * particles * all_steps;
  state.counters["steps_s_2threads"] = 1e-6 * both(1) * particles * all_steps;
  for (int half = 0; half < 2; ++half) {
    const std::string tag = half == 0 ? "_early" : "_late";
    state.counters["2vs1" + tag] = us(wall[half][0], steps[half][0]) / us(wall[half][1], steps[half][1]);
  }
  // The same ratio for the neighbour search, the rest of the RHS, and the rest of the step.
  // Per step: the last block may be short, so the two thread counts need not have run equally many.
  const double w1 = wall[0][0] + wall[1][0], w2 = wall[0][1] + wall[1][1];
  const double per = static_cast<double>(steps[0][1] + steps[1][1]) / static_cast<double>(steps[0][0] + steps[1][0]);
  state.counters["2vs1_search"] = per * search[0] / search[1];
  state.counters["2vs1_rhs_without_search"] = per * (rhs[0] - search[0]) / (rhs[1] - search[1]);
  state.counters["2vs1_outside_rhs"] = per * (w1 - rhs[0]) / (w2 - rhs[1]);
  state.counters["share_outside_rhs_2threads"] = (w2 - rhs[1]) / w2;
  state.counters["share_search_2threads"] = search[1] / w2;
  // Fused pair rows on 2 threads: imbalance = the busier thread over the mean; slowdown = the two
  // threads' summed row time over the 1-thread row time (1 when a thread runs as fast beside the other
  // as alone). 2vs1 of the rows = 2 / (imbalance x slowdown).
  state.counters["rows_imbalance"] = std::max(rows_2[0], rows_2[1]) / (0.5 * (rows_2[0] + rows_2[1]));
  state.counters["rows_slowdown"] = (rows_2[0] + rows_2[1]) / rows_1 / per;
  state.counters["particles"] = particles;
}
BENCHMARK(DamBreakRun)->Args({20, 1000})->Args({20, 300})->Args({20, 100})->ArgNames({"block", "t_end_ms"})->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

// The OpenMP wait policy this process runs with, as libgomp read it from the environment.
std::string wait_policy_label() {
  const char* policy = std::getenv("OMP_WAIT_POLICY");
  const char* spin = std::getenv("GOMP_SPINCOUNT");
  std::string s = std::string("OMP_WAIT_POLICY=") + (policy ? policy : "(unset)");
  return s + " GOMP_SPINCOUNT=" + (spin ? spin : "(unset: 300000)");
}

// A child process that keeps one core busy (the last this process may use), stopped until resume()
// and killed by the destructor (or with this process: PR_SET_PDEATHSIG).
class BusyCore {
 public:
  BusyCore() {
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    int core = -1;
    if (::sched_getaffinity(0, sizeof allowed, &allowed) == 0)
      for (int c = 0; c < CPU_SETSIZE; ++c)
        if (CPU_ISSET(c, &allowed)) core = c;
    pid_ = ::fork();
    if (pid_ == 0) {
      // The child of a multithreaded process: system calls and a loop only.
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (core >= 0) {
        cpu_set_t one;
        CPU_ZERO(&one);
        CPU_SET(core, &one);
        ::sched_setaffinity(0, sizeof one, &one);
      }
      ::raise(SIGSTOP);
      for (;;) __asm__ __volatile__("");  // an empty statement the compiler must keep
    }
    if (pid_ > 0) {
      int status = 0;
      ::waitpid(pid_, &status, WUNTRACED);  // stopped: it spins only between resume() and pause()
    }
  }
  BusyCore(const BusyCore&) = delete;
  BusyCore& operator=(const BusyCore&) = delete;
  ~BusyCore() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
  bool running() const { return pid_ > 0; }
  void resume() const { ::kill(pid_, SIGCONT); }
  void pause() const {
    ::kill(pid_, SIGSTOP);
    int status = 0;
    ::waitpid(pid_, &status, WUNTRACED);
  }

 private:
  pid_t pid_ = -1;
};

// The dam break after 200 steps of collapse, then `rounds` rounds of three blocks of `block` steps:
// 1 thread, 2 threads, and 2 threads while another process keeps one core busy (BusyCore). The three
// modes sample the same stretch of the run within a few hundred milliseconds of each other, so
// their ratios are free of the drift in machine speed. Counters: us/particle-step of each mode;
// 2vs1 = 1 thread / 2 threads (quiet); busy2vs1 = 1 thread / 2 threads beside the busy core (>= 1:
// two threads are no slower than one even so); busy_vs_quiet = 2 threads quiet / beside the busy core.
void DamBreakContention(benchmark::State& state) {
  const long block = state.range(0), rounds = state.range(1);
  std::array<double, 3> wall{};  // [mode]: 1 thread, 2 threads, 2 threads beside the busy core
  std::array<long, 3> steps{};
  double particles = 0.0;
  for (auto _ : state) {
    DamBreak run(sphmol::load_config(dam_break_yaml()));
    particles = static_cast<double>(run.sys->particles().size());
    const double never = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 200; ++k) run.integrator->step_toward(never);
    BusyCore busy;
    if (!busy.running()) {
      state.SkipWithError("fork failed: no competing process");
      break;
    }
    for (long r = 0; r < rounds; ++r)
      for (int mode = 0; mode < 3; ++mode) {
        omp_set_num_threads(mode == 0 ? 1 : 2);
        if (mode == 2) busy.resume();
        const double start = omp_get_wtime();
        for (long n = 0; n < block; ++n) run.integrator->step_toward(never);
        wall[mode] += omp_get_wtime() - start;
        if (mode == 2) busy.pause();
        steps[mode] += block;
      }
    benchmark::DoNotOptimize(run.y.data());
  }
  omp_set_num_threads(1);
  const auto us = [&](int mode) { return 1e6 * wall[mode] / (static_cast<double>(steps[mode]) * particles); };
  state.counters["us_1thread"] = us(0);
  state.counters["us_2threads"] = us(1);
  state.counters["us_2threads_busy"] = us(2);
  state.counters["2vs1"] = us(0) / us(1);
  state.counters["busy2vs1"] = us(0) / us(2);
  state.counters["busy_vs_quiet"] = us(1) / us(2);
  state.counters["particles"] = particles;
  state.SetLabel(wait_policy_label());
}
BENCHMARK(DamBreakContention)->Args({20, 15})->ArgNames({"block", "rounds"})->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

}  // namespace
