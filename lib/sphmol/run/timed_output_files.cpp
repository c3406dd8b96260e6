#include "sphmol/run/timed_output_files.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string_view>

namespace sphmol {

std::vector<std::pair<double, std::string>> timed_output_files(const OutputSink& out, std::string_view prefix) {
  std::vector<std::pair<double, std::string>> files;
  for (const auto& e : std::filesystem::directory_iterator(out.directory)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(prefix, 0) != 0 || e.path().extension() != ".csv") continue;
    // Only the names the run writes, <prefix><number>.csv: plot scripts quote these names, so a
    // planted file with a quote or a '|' in its name must never be picked up.
    char* end = nullptr;
    const char* number = name.c_str() + prefix.size();
    const double t = std::strtod(number, &end);
    if (end == number || std::string_view(end) != ".csv" || e.is_symlink() || !e.is_regular_file()) continue;
    if (std::string_view(number, end).find_first_not_of("0123456789.eE+-") != std::string_view::npos) continue;
    files.emplace_back(t, name);
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace sphmol
