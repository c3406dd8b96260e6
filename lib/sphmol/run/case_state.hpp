#pragma once
// A case's checkpoint state (Case::save_state / restore_state): named series of doubles as hex text
// of their bits (io/double_codec.hpp), so that a restarted run continues them to the bit; a malformed
// entry throws std::invalid_argument naming its key (the run reports it as a bad checkpoint).
#include <cstddef>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sphmol/io/double_codec.hpp"

namespace sphmol {

// The series under `key`.
inline std::vector<double> state_doubles(const nlohmann::json& state, const std::string& key) {
  if (!state.is_object() || !state.contains(key) || !state[key].is_string())
    throw std::invalid_argument(key + ": missing or not a string of hex digits");
  try {
    return decode_doubles(state[key].get<std::string>());
  } catch (const std::exception& e) {
    throw std::invalid_argument(key + ": " + e.what());
  }
}

// One double under `key`.
inline double state_double(const nlohmann::json& state, const std::string& key) {
  const std::vector<double> v = state_doubles(state, key);
  if (v.size() != 1) throw std::invalid_argument(key + ": " + std::to_string(v.size()) + " values, expected 1");
  return v[0];
}

// Series that go together (a row per output time): all of equal length, or none is restored.
inline void restore_columns(const nlohmann::json& state, std::initializer_list<std::pair<const char*, std::vector<double>*>> columns) {
  std::vector<std::vector<double>> read;
  for (const auto& [key, column] : columns) {
    read.push_back(state_doubles(state, key));
    if (read.back().size() != read.front().size())
      throw std::invalid_argument(std::string(key) + ": " + std::to_string(read.back().size()) + " values, expected " +
                                  std::to_string(read.front().size()) + " (" + columns.begin()->first + ")");
  }
  std::size_t k = 0;
  for (const auto& [key, column] : columns) *column = std::move(read[k++]);
}

}  // namespace sphmol
