#include "sphmol/run/timed_output_files.hpp"

#include <algorithm>
#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <string_view>

namespace sphmol {

std::string output_time_text(double t) {
  std::ostringstream s;
  s << std::setprecision(6) << t;
  return s.str();
}

std::vector<std::pair<double, std::string>> timed_output_files(const OutputSink& out, std::string_view prefix) {
  // Only what this run wrote: a reused folder may hold another run's files with the same prefix.
  std::vector<std::pair<double, std::string>> files;
  for (const std::string& name : out.written()) {
    if (name.rfind(prefix, 0) != 0) continue;
    // Only the names the run writes, <prefix><number>.csv: plot scripts quote these names, so a name
    // with a quote or a '|' in it must never be picked up (a checkpoint carries the list on restart).
    char* end = nullptr;
    const char* number = name.c_str() + prefix.size();
    const double t = std::strtod(number, &end);
    if (end == number || std::string_view(end) != ".csv") continue;
    if (std::string_view(number, end).find_first_not_of("0123456789.eE+-") != std::string_view::npos) continue;
    files.emplace_back(t, name);
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace sphmol
