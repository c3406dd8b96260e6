#pragma once
// Contiguous runs of an index map, for copying between two layouts of the same rows with one
// memcpy per run instead of one indexed load or store per row. The distributed evaluation copies
// the owned rows (dense in the integrator's state) to their rows in the local system (owned and
// halo rows in global-id order) and their rates back: on a lattice numbered row by row and a
// spatial partition, a rank's owned rows come in long runs between the halo's.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace sphmol::parallel {

// Rows [from, from + length) map to rows [to, to + length).
struct IndexRun {
  std::size_t from = 0, to = 0, length = 0;
};

// The runs of `at` over [0, n): each run is maximal, at[from + i] == to + i for i < length, but for
// the cut at max_length (> 0) rows, so that a loop over the runs splits evenly over threads. The
// runs cover [0, n) in order; any map (not only an increasing one) is allowed.
inline std::vector<IndexRun> index_runs(const std::uint32_t* at, std::size_t n, std::size_t max_length) {
  std::vector<IndexRun> runs;
  for (std::size_t i = 0; i < n;) {
    std::size_t e = i + 1;
    while (e < n && e - i < max_length && static_cast<std::size_t>(at[e]) == static_cast<std::size_t>(at[i]) + (e - i)) ++e;
    runs.push_back({i, at[i], e - i});
    i = e;
  }
  return runs;
}

// to[run.to + i] = from[run.from + i] for i < run.length: over the runs of `at`, to[at[i]] = from[i].
inline void scatter_run(const IndexRun& run, const double* from, double* to) {
  std::memcpy(to + run.to, from + run.from, run.length * sizeof(double));
}

// to[run.from + i] = from[run.to + i] for i < run.length: over the runs of `at`, to[i] = from[at[i]].
inline void gather_run(const IndexRun& run, const double* from, double* to) {
  std::memcpy(to + run.from, from + run.to, run.length * sizeof(double));
}

}  // namespace sphmol::parallel
