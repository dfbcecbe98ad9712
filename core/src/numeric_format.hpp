#pragma once
// Private helper: numbers in error messages, shortest form that round-trips.
#include <charconv>
#include <cmath>
#include <string>

namespace covopt::internal {

inline std::string FormatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace covopt::internal
