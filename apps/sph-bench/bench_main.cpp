// sph-bench: Google Benchmark programs for the hot paths. Throughput is reported as directed pair
// interactions per second ("pairs/s", and its inverse "ns/pair") and as wall time per particle per
// RHS evaluation ("us/particle"); compare variants (threads, searches, skin, order) from one run, as
// ratios of medians (--benchmark_repetitions=5), since a shared machine is noisy.
//   sph-bench --benchmark_filter=Rhs/            RHS, Poiseuille (laminar), shock tube (compressible) and
//                                                dam break (free surface), 1e4..1e6 particles, 1 and 2 threads
//   sph-bench --benchmark_filter=RhsPasses       fused pair passes vs the stored pair list (1 thread)
//   sph-bench --benchmark_filter=RhsScaling      Taylor-Green RHS from 1e3 to 1e6 particles
//   sph-bench --benchmark_filter=RhsReorder      RHS with the workspace in lattice / shuffled order,
//                                                locality reordering off / on (1e5 particles)
//   sph-bench --benchmark_filter=Search          neighbour-list build + query, cell list (1, 2 threads) vs kd-tree
//   sph-bench --benchmark_filter=Rebuilds        Verlet rebuilds per 100 ARKODE steps, skin 0.3 h vs 0
//   sph-bench --benchmark_filter=DamBreakStep    end to end: dam-break leapfrog steps, 1 and 2 threads
//   sph-bench --benchmark_filter=DamBreakRun     the whole dam-break run, alternating 1 and 2 threads every
//                                                20 steps: the 2-vs-1 ratio (bench_dam_break.cpp)
//   sph-bench --benchmark_filter=DamBreakContention  dam-break steps on 1 thread, 2 threads, and 2 threads
//                                                beside a process that keeps one core busy (ratios)
//   sph-bench --benchmark_filter=DamBreak3DStep  end to end in 3D: a dam break in a box, 1.1e5 particles,
//                                                1 and 2 threads (bench_dam_break_3d.cpp)
//   scripts/bench_memory.sh                      peak memory per particle (one process per size)
#include <benchmark/benchmark.h>
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "sphmol/config/config.hpp"
#include "sphmol/neighbors/neighbor_search.hpp"
#include "sphmol/rhs/assemble.hpp"
#include "sphmol/run/openmp_wait_policy.hpp"
#include "sphmol/cases/case_module.hpp"
#include "sphmol/scenes/box_scene.hpp"
#include "sphmol/time/integrator.hpp"

namespace {

std::string num(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

std::string verification(const char* name) { return std::string(SPHMOL_SOURCE_DIR) + "/verification/" + name; }

// The Poiseuille verification case scaled to about n fluid particles (square spacing, 100 to 500
// across the channel, periodic length a multiple of the height).
sphmol::Config poiseuille(long n, const std::string& search) {
  const long across = n <= 10'000 ? 100 : n <= 100'000 ? 200 : 500;
  const double lengths = static_cast<double>(n) / static_cast<double>(across * across);
  return sphmol::load_config(verification("poiseuille.yaml"),
                             {"discretization.particles_across=" + std::to_string(across),
                              "geometry.channel_length=" + num(1e-3 * lengths), "discretization.neighbor_search=" + search});
}

// The 2D shock tube (ideal gas, continuity density, energy and dh/dt in the state, artificial
// viscosity) at its shipped spacing, widened to about n particles (320 columns along the tube).
// Variable h needs the kd-tree (the cell list assumes one radius), whatever `search` asks.
sphmol::Config shock_tube(long n, const std::string&) {
  const double dx = 2.5e-3;
  const long rows = std::max(1L, std::lround(static_cast<double>(n) / 320.0));
  return sphmol::load_config(verification("shock_tube.yaml"), {"geometry.tube_width=" + num(rows * dx)});
}

// The periodic Taylor-Green vortex with about n particles (sqrt(n) across).
sphmol::Config taylor_green(long n, const std::string& search = "cell_list") {
  const long across = std::lround(std::sqrt(static_cast<double>(n)));
  return sphmol::load_config(verification("taylor_green.yaml"), {"discretization.particles_across=" + std::to_string(across),
                                                                 "discretization.neighbor_search=" + search});
}

// The dam break (free surface, continuity + delta-SPH, artificial viscosity, dynamic walls) with the
// spacing scaled so that the column holds about n fluid particles (20,000 at the shipped dp = 0.01 m).
sphmol::Config dam_break(long n, const std::string& search) {
  // The column (1 m x 2 m) and the tank (4 m x 3 m) must be whole numbers of spacings.
  const double dp = 1.0 / std::round(100.0 * std::sqrt(static_cast<double>(n) / 20'000.0));
  return sphmol::load_config(verification("dam_break.yaml"),
                             {"discretization.spacing=" + num(dp), "discretization.neighbor_search=" + search});
}

std::unique_ptr<sphmol::SphSystem<2>> build(const sphmol::Config& c) {
  auto cs = sphmol::make_case<2>(c);
  return cs->build(c);
}

void set_rhs_counters(benchmark::State& state, const sphmol::SphSystem<2>& sys) {
  const double pairs = static_cast<double>(sys.active_pairs());
  const double particles = static_cast<double>(sys.particles().size());
  using C = benchmark::Counter;
  state.counters["pairs/s"] = C(pairs, C::kIsIterationInvariantRate);
  state.counters["ns/pair"] = C(pairs * 1e-9, C::kIsIterationInvariantRate | C::kInvert);
  state.counters["us/particle"] = C(particles * 1e-6, C::kIsIterationInvariantRate | C::kInvert);
  state.counters["particles"] = particles;
  state.counters["pairs/particle"] = pairs / particles;
}

void time_rhs(benchmark::State& state, sphmol::SphSystem<2>& sys) {
  std::vector<double> y = sys.initial_state(), f(y.size());
  sys.rhs(0.0, y.data(), f.data());  // builds the pair list once
  for (auto _ : state) {
    sys.rhs(0.0, y.data(), f.data());
    benchmark::DoNotOptimize(f.data());
  }
  set_rhs_counters(state, sys);
}

// RHS throughput of one formulation; args: particles, threads.
void Rhs(benchmark::State& state, sphmol::Config (*config)(long, const std::string&)) {
  omp_set_num_threads(static_cast<int>(state.range(1)));
  auto sys = build(config(state.range(0), "cell_list"));
  time_rhs(state, *sys);
  omp_set_num_threads(1);
}
BENCHMARK_CAPTURE(Rhs, poiseuille, poiseuille)
    ->ArgsProduct({{10'000, 100'000, 1'000'000}, {1, 2}})
    ->ArgNames({"n", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(Rhs, shock_tube, shock_tube)
    ->ArgsProduct({{10'000, 100'000, 1'000'000}, {1, 2}})
    ->ArgNames({"n", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(Rhs, dam_break, dam_break)
    ->ArgsProduct({{10'000, 100'000, 1'000'000}, {1, 2}})
    ->ArgNames({"n", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(Rhs, taylor_green, taylor_green)
    ->ArgsProduct({{1'000, 10'000, 100'000, 1'000'000}, {1, 2}})
    ->ArgNames({"n", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Fused pair passes (rhs/fused_pair_pass.hpp) against the stored active-pair list, and the dam break's
// combined weakly compressible row against its four terms apart; 1 thread. Args: fused (0/1),
// combined (0/1), particles.
void RhsPasses(benchmark::State& state, sphmol::Config (*config)(long, const std::string&)) {
  omp_set_num_threads(1);
  auto c = config(state.range(2), "cell_list");
  c.discretization.pair_passes = state.range(0) != 0 ? "fused" : "stored";
  c.discretization.combine_terms = state.range(1) != 0;
  auto sys = build(c);
  time_rhs(state, *sys);
}
BENCHMARK_CAPTURE(RhsPasses, dam_break, dam_break)
    ->ArgsProduct({{0, 1}, {0, 1}, {100'000}})
    ->ArgNames({"fused", "combined", "n"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(RhsPasses, shock_tube, shock_tube)
    ->ArgsProduct({{0, 1}, {1}, {100'000}})
    ->ArgNames({"fused", "combined", "n"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(RhsPasses, poiseuille, poiseuille)
    ->ArgsProduct({{0, 1}, {1}, {100'000}})
    ->ArgNames({"fused", "combined", "n"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(RhsPasses, taylor_green, taylor_green)
    ->ArgsProduct({{0, 1}, {1}, {10'000, 100'000, 1'000'000}})
    ->ArgNames({"fused", "combined", "n"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Locality: a Taylor-Green lattice (fluid only, periodic) in lattice order or randomly shuffled
// (standing for a flow that has mixed its particles), with reordering off (0) or on (1); 1 thread.
void RhsReorder(benchmark::State& state) {
  const bool shuffled = state.range(1) != 0, reorder = state.range(2) != 0;
  omp_set_num_threads(1);
  const auto c = taylor_green(state.range(0));
  sphmol::BoxScene s = sphmol::build_box_scene(c, 1.0, 1.0, 1.0, sphmol::BoxWalls<2>{}, true);
  if (shuffled) {
    auto& P = s.particles;
    std::vector<std::size_t> order(P.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), std::mt19937(42));
    sphmol::Particles<2> Q;
    for (const std::size_t i : order)
      Q.add(P.kind[i], {P.x[0][i], P.x[1][i]}, {P.v[0][i], P.v[1][i]}, P.mass[i], P.rho[i]);
    s.particles = std::move(Q);
  }
  auto sys = sphmol::assemble_system<2>(c, std::move(s.particles), s.domain, s.spacing);
  sys->set_reorder(reorder);
  time_rhs(state, *sys);
}
BENCHMARK(RhsReorder)
    ->ArgsProduct({{100'000}, {0, 1}, {0, 1}})
    ->ArgNames({"n", "shuffled", "reorder"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Neighbour-list build + query (the whole PairList) per particle, Poiseuille lattice, 1 thread
// (cell_list_2threads: the cell list on 2 threads; its list is the same for any thread count).
void Search(benchmark::State& state, const char* method, int threads = 1) {
  omp_set_num_threads(threads);
  const auto c = poiseuille(state.range(0), method);
  auto sys = build(c);
  const auto& P = sys->particles();
  sphmol::SearchInput<2> in;
  for (int d = 0; d < 2; ++d) in.x[d] = P.x[d].data();
  in.kind = P.kind.data();
  in.n = P.size();
  in.domain = &sys->domain();
  in.radius = sys->pair_list().list_radius();
  auto search = sphmol::make_neighbor_search<2>(method);
  sphmol::PairList out;
  for (auto _ : state) {
    search->build(in, out);
    benchmark::DoNotOptimize(out.j.data());
  }
  using C = benchmark::Counter;
  state.counters["us/particle"] = C(static_cast<double>(in.n) * 1e-6, C::kIsIterationInvariantRate | C::kInvert);
  state.counters["pairs/particle"] = static_cast<double>(out.pairs()) / static_cast<double>(in.n);
}
BENCHMARK_CAPTURE(Search, cell_list, "cell_list")->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Search, cell_list_2threads, "cell_list", 2)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Search, kdtree, "kdtree")->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond)->UseRealTime();

// Verlet rebuilds per 100 accepted ARKODE steps of the Taylor-Green vortex (1e4 particles, U = 1,
// the shipped DP 5(4) tolerances), skin in units of h as the argument x 10. One iteration = 100 steps.
void Rebuilds(benchmark::State& state) {
  omp_set_num_threads(1);
  const double skin = static_cast<double>(state.range(0)) / 10.0;
  const auto c = sphmol::load_config(verification("taylor_green.yaml"),
                                    {"discretization.particles_across=100", "discretization.skin=" + num(skin)});
  double rebuilds = 0.0, evals = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    auto sys = build(c);
    std::vector<double> y = sys->initial_state();
    auto integ = sphmol::make_integrator(c.time);
    integ->initialize(*sys, 0.0, y.data());
    const long r0 = sys->pair_list().rebuilds(), e0 = sys->rhs_evaluations();
    state.ResumeTiming();
    double t = 0.0;
    for (int s = 0; s < 100; ++s) t = integ->step_toward(1e9);
    rebuilds += static_cast<double>(sys->pair_list().rebuilds() - r0);
    evals += static_cast<double>(sys->rhs_evaluations() - e0);
    benchmark::DoNotOptimize(t);
  }
  const double it = static_cast<double>(state.iterations());
  state.counters["rebuilds/100steps"] = rebuilds / it;
  state.counters["rhs/100steps"] = evals / it;
}
BENCHMARK(Rebuilds)->Arg(3)->Arg(0)->ArgName("skin_x10")->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

// Peak resident memory per particle of a Taylor-Green run (system, pair lists, the case's leapfrog)
// after 3 steps, with the stored pair list (fused 0) or fused pair passes (fused 1). getrusage's peak covers the whole process, so run one size per
// process (scripts/bench_memory.sh); the value is an upper bound that includes the program itself.
void Memory(benchmark::State& state) {
  omp_set_num_threads(1);
  auto c = taylor_green(state.range(0));
  c.discretization.pair_passes = state.range(1) != 0 ? "fused" : "stored";
  double particles = 0.0;
  for (auto _ : state) {
    auto sys = build(c);
    std::vector<double> y = sys->initial_state();
    auto integ = sphmol::make_integrator(c.time);
    integ->initialize(*sys, 0.0, y.data());
    for (int s = 0; s < 3; ++s) integ->step_toward(1e9);
    particles = static_cast<double>(sys->particles().size());
  }
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  state.counters["maxrss_MiB"] = static_cast<double>(u.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
  state.counters["bytes/particle"] = static_cast<double>(u.ru_maxrss) * 1024.0 / particles;
}
BENCHMARK(Memory)
    ->ArgsProduct({{10'000, 100'000, 1'000'000}, {0, 1}})
    ->ArgNames({"n", "fused"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace

// As sph-mol: a short spin at barriers unless the environment chooses (run/openmp_wait_policy.hpp);
// the benchmarks use up to two threads. Set OMP_WAIT_POLICY or GOMP_SPINCOUNT to measure another.
int main(int argc, char** argv) {
  sphmol::bound_openmp_spin(std::min(2, omp_get_num_procs()), argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
