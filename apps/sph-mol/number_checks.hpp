#pragma once
// Bounds on numeric command-line options with messages in the option's own terms: CLI11's
// PositiveNumber and NonNegativeNumber are ranges up to the largest double, which their messages
// print in full (300 digits).
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <string>

namespace sphmol::app {

// A finite number x with x > lo (strict) or x >= lo.
inline CLI::Validator number_above(double lo, bool strict) {
  const std::string bound = std::string(strict ? "> " : ">= ") + CLI::detail::to_string(lo);
  return CLI::Validator(
      [lo, strict, bound](std::string& text) -> std::string {
        char* end = nullptr;
        const double x = std::strtod(text.c_str(), &end);
        const bool number = !text.empty() && end == text.c_str() + text.size() && std::isfinite(x);
        if (number && (strict ? x > lo : x >= lo)) return {};
        return "Value " + text + " is not a number " + bound;
      },
      "NUMBER " + bound);
}

inline CLI::Validator positive_number() { return number_above(0.0, true); }
inline CLI::Validator non_negative_number() { return number_above(0.0, false); }

}  // namespace sphmol::app
