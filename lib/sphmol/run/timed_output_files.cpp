#include "sphmol/run/timed_output_files.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace sphmol {

std::vector<std::pair<double, std::string>> timed_output_files(const OutputSink& out, std::string_view prefix) {
  std::vector<std::pair<double, std::string>> files;
  for (const auto& e : std::filesystem::directory_iterator(out.directory)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(prefix, 0) != 0 || e.path().extension() != ".csv") continue;
    files.emplace_back(std::strtod(name.c_str() + prefix.size(), nullptr), name);
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace sphmol
