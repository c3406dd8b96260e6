#pragma once
// A counter of an integrator's checkpoint state (integrator_state): 0 when the key is missing, as in
// checkpoints written before the counter was saved, so those still restart (the summary then counts
// only from the restart for that counter).
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace sphmol {

inline long saved_count(const nlohmann::json& state, const char* key) {
  if (!state.contains(key)) return 0;
  const auto& v = state.at(key);
  if (!(v.is_number_unsigned() || (v.is_number_integer() && v.get<long>() >= 0)))
    throw std::runtime_error(std::string(key) + ": " + v.dump() + " is not a count >= 0");
  return v.get<long>();
}

}  // namespace sphmol
