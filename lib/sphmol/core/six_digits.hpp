#pragma once
// A number at six significant digits (printf's %g): for messages and file names where a computed
// value (0.1 + 0.2, a spacing times a count) must not print its round-off digits.
#include <charconv>
#include <string>

namespace sphmol {

inline std::string six_digits(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 6);
  return std::string(buf, r.ptr);
}

}  // namespace sphmol
