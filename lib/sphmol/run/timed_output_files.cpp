#include "sphmol/run/timed_output_files.hpp"

#include <algorithm>
#include <cstdlib>

namespace sphmol {

std::vector<std::pair<double, std::string>> timed_output_files(const OutputSink& out, std::string_view prefix) {
  // Only what this run wrote: a reused folder may hold another run's files with the same prefix.
  std::vector<std::pair<double, std::string>> files;
  for (const std::string& name : out.written()) {
    if (name.rfind(prefix, 0) != 0 || name.size() < 4 || name.compare(name.size() - 4, 4, ".csv") != 0) continue;
    files.emplace_back(std::strtod(name.c_str() + prefix.size(), nullptr), name);
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace sphmol
