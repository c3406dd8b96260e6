#pragma once
// A shipped verification file run in this process, with `--set`-style overrides, writing no files:
// its summary, as `sph-mol --config verification/FILE --set ...` would write it.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sphmol/config/config.hpp"
#include "sphmol/run/run_case.hpp"

namespace in_process {

inline nlohmann::json run_verification(const std::string& file, const std::vector<std::string>& overrides) {
  const sphmol::Config c = sphmol::load_config(std::string(SPHMOL_SOURCE_DIR) + "/verification/" + file, overrides);
  sphmol::RunOptions o;
  o.write_files = false;
  return sphmol::run_case(c, o);
}

}  // namespace in_process
