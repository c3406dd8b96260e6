// sph-bench: Google Benchmark programs for the hot paths. Throughput is reported as directed pair
// interactions per second ("pairs/s") and as wall time per particle per RHS evaluation ("us/particle");
// compare variants (threads, searches) from one run, as ratios, since machines are noisy.
//   sph-bench --benchmark_filter=Rhs          RHS of the Poiseuille formulation, 1e4..1e6 particles
//   sph-bench --benchmark_filter=Search       neighbour-list build, cell list vs CGAL kd-tree
#include <benchmark/benchmark.h>
#include <omp.h>

#include <string>

#include "sphmol/config/config.hpp"
#include "sphmol/neighbors/neighbor_search.hpp"
#include "sphmol/run/case_registry.hpp"

namespace {

// The Poiseuille verification case scaled to about n fluid particles (square spacing, 100 to 500
// across the channel, periodic length a multiple of the height).
sphmol::Config poiseuille(long n, const std::string& search) {
  long across = n <= 10'000 ? 100 : n <= 100'000 ? 200 : 500;
  const double lengths = static_cast<double>(n) / (across * across);
  const std::string path = std::string(SPHMOL_SOURCE_DIR) + "/verification/poiseuille.yaml";
  return sphmol::load_config(path, {"discretization.particles_across=" + std::to_string(across),
                                    "geometry.channel_length=" + std::to_string(1e-3 * lengths),
                                    "discretization.neighbor_search=" + search});
}

std::unique_ptr<sphmol::SphSystem<2>> build(const sphmol::Config& c) {
  auto cs = sphmol::case_registry().at(c.case_name).d2();
  return cs->build(c);
}

void Rhs(benchmark::State& state) {
  const long n = state.range(0);
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  auto sys = build(poiseuille(n, "cell_list"));
  std::vector<double> y = sys->initial_state(), f(y.size());
  sys->rhs(0.0, y.data(), f.data());  // builds the pair list once
  for (auto _ : state) {
    sys->rhs(0.0, y.data(), f.data());
    benchmark::DoNotOptimize(f.data());
  }
  const double pairs = static_cast<double>(sys->active_pairs());
  const double particles = static_cast<double>(sys->particles().size());
  state.counters["pairs/s"] = benchmark::Counter(pairs, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["us/particle"] = benchmark::Counter(particles * 1e-6, benchmark::Counter::kIsIterationInvariantRate |
                                                                           benchmark::Counter::kInvert);
  state.counters["particles"] = particles;
  omp_set_num_threads(1);
}
BENCHMARK(Rhs)->ArgsProduct({{10'000, 100'000, 1'000'000}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime();

void Search(benchmark::State& state, const char* method) {
  const long n = state.range(0);
  const auto c = poiseuille(n, method);
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
  state.counters["us/particle"] = benchmark::Counter(static_cast<double>(in.n) * 1e-6, benchmark::Counter::kIsIterationInvariantRate |
                                                                                         benchmark::Counter::kInvert);
}
BENCHMARK_CAPTURE(Search, cell_list, "cell_list")->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(Search, kdtree, "kdtree")->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
