#pragma once
/// @file json_number.hpp
/// Numbers for JSON (private to covopt_report).

#include <cmath>
#include <optional>

#include <nlohmann/json.hpp>

namespace covopt::report::internal {

/// A number, or null when it is not finite (JSON has no NaN or Infinity).
inline nlohmann::ordered_json Number(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}
inline nlohmann::ordered_json Number(const std::optional<double>& value) {
  return value ? Number(*value) : nlohmann::ordered_json(nullptr);
}

}  // namespace covopt::report::internal
