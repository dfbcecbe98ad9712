// The library's one number formatter (covopt/core/number_format.hpp).
#include "covopt/core/number_format.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

namespace covopt {
namespace {

/// std::to_chars with a precision, into a string long enough for any double: the integer
/// part of a fixed-point number has up to 309 digits, the exponential form far fewer.
std::string WithPrecision(double value, std::chars_format format, int precision) {
  precision = std::max(precision, 0);
  constexpr int kStackPrecision = 64;
  if (precision <= kStackPrecision) {
    // The usual case, on the stack: one allocation (or none) for the result alone.
    char buffer[kStackPrecision + 330];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, format, precision);
    return std::string(buffer, result.ptr);
  }
  std::string text(static_cast<std::size_t>(precision) + 330, '\0');
  const auto result = std::to_chars(text.data(), text.data() + text.size(), value, format, precision);
  text.resize(static_cast<std::size_t>(result.ptr - text.data()));
  return text;
}

constexpr double kPowersOfTen[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8,
                                   1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

}  // namespace

std::string FormatShortest(double value) {
  if (std::isnan(value)) return "nan";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string FormatSignificant(double value, int digits) {
  digits = std::max(digits, 1);
  // An integer below 10^digits: %g prints its digits alone (the decimals it would add are
  // zeros and are stripped), so an integer conversion writes the same text several times
  // faster (limits, counts and safety factors are mostly such numbers).
  if (digits <= 15 && value == std::trunc(value) && std::abs(value) < kPowersOfTen[digits] &&
      !(value == 0.0 && std::signbit(value))) {
    char buffer[24];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, static_cast<long long>(value));
    return std::string(buffer, result.ptr);
  }
  return WithPrecision(value, std::chars_format::general, digits);
}

std::string FormatFixed(double value, int decimals) {
  return WithPrecision(value, std::chars_format::fixed, decimals);
}

std::string FormatScientific(double value, int decimals) {
  return WithPrecision(value, std::chars_format::scientific, decimals);
}

}  // namespace covopt
