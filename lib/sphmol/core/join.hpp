#pragma once
// Items joined with ", " (lists of names in error messages).
#include <string>
#include <vector>

namespace sphmol {

inline std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) {
    if (!out.empty()) out += ", ";
    out += s;
  }
  return out;
}

}  // namespace sphmol
