#pragma once
// Shared by the study subcommands (compare, converge, stability): load the config with --set
// overrides, reporting config errors like the main command (exit code 2), and command-line values
// that only the study itself can judge (exit code 2, naming the option).
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "sphmol/config/config.hpp"
#include "sphmol/config/yaml_reader.hpp"
#include "sphmol/studies/integrator_spec.hpp"

namespace sphmol::app {

inline std::optional<Config> load_study_config(const std::string& path, const std::vector<std::string>& overrides,
                                               const char* who) {
  try {
    Config c = load_config(path, overrides);
    for (const auto& n : c.notices) std::cerr << "sph-mol " << who << ": " << n << '\n';
    return c;
  } catch (const ConfigError& e) {
    std::cerr << "sph-mol " << who << ": config error: " << e.what() << '\n';
    return std::nullopt;
  }
}

// Prints "sph-mol WHO: OPTION: MESSAGE" and returns the bad-input exit code.
inline int bad_option(const char* who, const std::string& option, const std::string& message) {
  std::cerr << "sph-mol " << who << ": " << option << ": " << message << '\n';
  return 2;
}

// --integrators LIST, or nullopt after reporting the bad entry.
inline std::optional<std::vector<IntegratorSpec>> parse_integrators_option(const char* who, const std::string& list,
                                                                          const std::string& default_table) {
  try {
    return parse_integrator_list(list, default_table);
  } catch (const std::invalid_argument& e) {
    bad_option(who, "--integrators", e.what());
    return std::nullopt;
  }
}

// A sweep given coarse to fine: each value below the one before (the fastest-at-error summary reads
// the runs in that order, and a repeated value would run twice). True when it is, else reports it.
inline bool coarse_to_fine_ok(const char* who, const std::string& option, const std::vector<double>& values) {
  for (std::size_t k = 1; k < values.size(); ++k)
    if (!(values[k] < values[k - 1])) {
      std::string list;
      for (const double v : values) list += (list.empty() ? "" : ",") + number_text(v);
      bad_option(who, option, "must go from coarse to fine, each value smaller than the one before (got " + list + ")");
      return false;
    }
  return true;
}

// A list without a repeated value (a repeated one would run, or be reported, twice). True when it
// is, else reports it.
inline bool distinct_ok(const char* who, const std::string& option, const std::vector<double>& values) {
  for (std::size_t k = 0; k < values.size(); ++k)
    for (std::size_t m = 0; m < k; ++m)
      if (values[k] == values[m]) {
        bad_option(who, option, "gives " + number_text(values[k]) + " twice");
        return false;
      }
  return true;
}

// The same --output checks as the run command's (command_line.hpp).
inline bool output_option_ok(const char* who, const std::string& output) {
  const auto problem = output_option_problem(output);
  if (!problem) return true;
  bad_option(who, "--output", *problem);
  return false;
}

}  // namespace sphmol::app
