#pragma once
// A run over ranks measures what the serial run measures: its summary's final_errors equal the
// serial ones, except the keys of a case's own per-evaluation monitor (`output_only`), which a run
// over ranks evaluates at output times only and must still report.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

inline void check_same_measurements(const nlohmann::json& split_summary, const nlohmann::json& serial_summary,
                                    const std::vector<std::string>& output_only) {
  nlohmann::json a = split_summary["final_errors"], b = serial_summary["final_errors"];
  for (const auto& k : output_only) {
    CHECK(a.contains(k));
    a.erase(k);
    b.erase(k);
  }
  CHECK(a == b);
}
