#pragma once
// A run over ranks measures what the serial run measures: its summary's final_errors equal the
// serial ones, the case's per-evaluation monitors included (rhs/monitor.hpp).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

inline void check_same_measurements(const nlohmann::json& split_summary, const nlohmann::json& serial_summary) {
  CHECK(split_summary["final_errors"] == serial_summary["final_errors"]);
}
