#pragma once
// A run of c writing its files into `dir`: serial without a partitioner, over the ranks with one.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "sphmol/config/config.hpp"
#include "sphmol/run/run_case.hpp"

namespace sphmol::parallel::testing {

inline nlohmann::json run_into(const Config& c, const RunPartitioner* partitioner, const std::filesystem::path& dir) {
  RunOptions opt;
  opt.write_files = true;
  opt.output_dir = dir.string();
  opt.partitioner = partitioner;
  return run_case(c, opt);
}

}  // namespace sphmol::parallel::testing
