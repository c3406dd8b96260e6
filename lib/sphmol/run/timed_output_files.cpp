#include "sphmol/run/timed_output_files.hpp"

#include "sphmol/core/six_digits.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <string_view>

namespace sphmol {

std::string output_time_text(double t) { return six_digits(t); }

std::vector<std::pair<double, std::string>> timed_output_files(const OutputSink& out, std::string_view prefix) {
  // Only what this run wrote: a reused folder may hold another run's files with the same prefix.
  std::vector<std::pair<double, std::string>> files;
  for (const std::string& name : out.written()) {
    if (name.rfind(prefix, 0) != 0) continue;
    // Only the names the run writes, <prefix><number>.csv: plot scripts quote these names, so a name
    // with a quote or a '|' in it must never be picked up (a checkpoint carries the list on restart).
    // The time is what lies between the prefix and ".csv", parsed whole: strtod on "1.csv" would take
    // "1." and leave "csv", and the file of t = 1 was never drawn.
    constexpr std::string_view suffix = ".csv";
    if (name.size() <= prefix.size() + suffix.size() || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) continue;
    const std::string number = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (number.find_first_not_of("0123456789.eE+-") != std::string::npos) continue;
    char* end = nullptr;
    const double t = std::strtod(number.c_str(), &end);
    if (end != number.c_str() + number.size()) continue;
    files.emplace_back(t, name);
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace sphmol
