#pragma once
// A run over ranks against the serial run of the same config (rank 0 runs the reference): the same
// steps, rejections, RHS evaluations (more by those an integrator makes on a new share per
// repartition), Krylov iterations and stage solves, the same final state to the bit and the same
// measurements.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/parallel/communicator.hpp"
#include "sphmol/parallel/mpi_run.hpp"
#include "sphmol/run/run_case.hpp"
#include "same_measurements.hpp"

namespace sphmol::parallel::testing {

inline std::string verification(const std::string& name) { return std::string(SPHMOL_SOURCE_DIR) + "/verification/" + name; }

struct Finished {
  nlohmann::json summary;
  std::vector<double> y;
};

// A run of c: serial without a partitioner; files only with an output folder.
inline Finished run(const Config& c, const RunPartitioner* partitioner, const std::string& restart_from = "",
                    const std::string& output_dir = "") {
  Finished f;
  RunOptions opt;
  opt.write_files = !output_dir.empty();
  opt.output_dir = output_dir;
  opt.restart_from = restart_from;
  opt.final_state = &f.y;
  opt.partitioner = partitioner;
  f.summary = run_case(c, opt);
  return f;
}

// Entries whose bits differ (0: the same state to the bit).
inline std::size_t differing_bits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return std::max(a.size(), b.size());
  std::size_t n = 0;
  for (std::size_t k = 0; k < a.size(); ++k) n += std::memcmp(&a[k], &b[k], sizeof(double)) != 0;
  return n;
}

inline bool same_bits(const std::vector<double>& a, const std::vector<double>& b) { return differing_bits(a, b) == 0; }

// The largest difference between two whole states relative to each quantity's own scale: positions
// against the largest |x| over all position blocks, velocities against the largest |v|, then the
// fluid densities and the wall densities each against their largest value. (A velocity component
// that is zero but for round-off, such as a channel's cross-stream one, is measured against the
// flow's speed, not against itself.)
inline double relative_difference(const std::vector<double>& a, const std::vector<double>& b, const nlohmann::json& summary) {
  if (a.size() != b.size()) return INFINITY;
  const auto D = summary["dimension"].get<std::size_t>();
  const auto n = summary["particles"]["fluid"].get<std::size_t>();
  const std::size_t fluid_blocks = a.size() / n;  // positions, velocities, density
  std::vector<std::pair<std::size_t, std::size_t>> groups{{0, D * n}, {D * n, 2 * D * n}};
  if (fluid_blocks > 2 * D) groups.emplace_back(2 * D * n, fluid_blocks * n);
  if (fluid_blocks * n < a.size()) groups.emplace_back(fluid_blocks * n, a.size());
  double worst = 0.0;
  for (const auto& [lo, hi] : groups) {
    double scale = 0.0, diff = 0.0;
    for (std::size_t k = lo; k < hi; ++k) {
      scale = std::max(scale, std::abs(b[k]));
      diff = std::max(diff, std::abs(a[k] - b[k]));
    }
    worst = std::max(worst, scale > 0.0 ? diff / scale : diff);
  }
  return worst;
}

// The serial reference of a config, once per config, on rank 0.
inline const Finished& serial_run(const Config& c) {
  static std::map<std::string, Finished> runs;
  const std::string key = to_yaml(c);
  if (!runs.count(key)) runs.emplace(key, run(c, nullptr));
  return runs.at(key);
}

// `rebalance`: the imbalance past which the particles are partitioned again (1: at every re-plan).
// `evaluations_per_start`: the RHS evaluations of the integrator's start, which each repartition
// repeats (leapfrog_imex: 2, the full f and then the split one; arkode_imex: 1, its frozen operator
// recorded again; arkode_erk and cvode_adams: 0, their vectors move as they are).
inline Finished check_same_as_serial(const Config& c, double rebalance = 1.2, long evaluations_per_start = 1) {
  const Communicator comm;
  const MpiRunPartitioner partitioner(comm, MpiRunPartitioner::default_tolerance, rebalance);
  const Finished split = run(c, &partitioner);
  CHECK(split.summary["status"] == "completed");
  if (comm.rank() == 0) {
    const Finished& serial = serial_run(c);
    REQUIRE(serial.summary["status"] == "completed");
    CHECK(split.summary["steps"] == serial.summary["steps"]);
    CHECK(split.summary["rejected_steps"] == serial.summary["rejected_steps"]);
    const long repartitions = split.summary["parallel"]["repartitions"].get<long>();
    CHECK(split.summary["rhs_evals"].get<long>() == serial.summary["rhs_evals"].get<long>() + evaluations_per_start * repartitions);
    CHECK(split.summary["integrator"].value("krylov_iterations", -1L) == serial.summary["integrator"].value("krylov_iterations", -1L));
    CHECK(split.summary["integrator"].value("stage_solves", -1L) == serial.summary["integrator"].value("stage_solves", -1L));
    INFO(comm.size() << " ranks, " << split.summary["steps"] << " steps, " << split.y.size() << " state values");
    INFO("largest relative difference from the serial state: " << relative_difference(split.y, serial.y, serial.summary));
    CHECK(differing_bits(split.y, serial.y) == 0);
    check_same_measurements(split.summary, serial.summary);
    // Fluid taken out of the run (run/outflow.hpp): the same particles, mass and first exit.
    CHECK(split.summary["outflow"] == serial.summary["outflow"]);
    CHECK(split.summary["parallel"]["ranks"] == comm.size());
  }
  return split;
}

}  // namespace sphmol::parallel::testing
