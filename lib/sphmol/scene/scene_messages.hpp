#pragma once
// The pieces of the scene builder's error messages: axis names, numbers as a user wrote them
// (shortest form, as the stream prints them) and the ConfigError at a key's location.
#include <sstream>
#include <string>

#include "sphmol/config/config.hpp"

namespace sphmol::scene_messages {

inline const char* const kAxisName[] = {"x", "y", "z"};

inline std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

[[noreturn]] inline void fail(const std::string& where, const std::string& what) { throw ConfigError(where + ": " + what); }

}  // namespace sphmol::scene_messages
