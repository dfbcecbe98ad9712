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
  std::string text(static_cast<std::size_t>(precision) + 330, '\0');
  const auto result = std::to_chars(text.data(), text.data() + text.size(), value, format, precision);
  text.resize(static_cast<std::size_t>(result.ptr - text.data()));
  return text;
}

}  // namespace

std::string FormatShortest(double value) {
  if (std::isnan(value)) return "nan";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string FormatSignificant(double value, int digits) {
  return WithPrecision(value, std::chars_format::general, std::max(digits, 1));
}

std::string FormatFixed(double value, int decimals) {
  return WithPrecision(value, std::chars_format::fixed, decimals);
}

std::string FormatScientific(double value, int decimals) {
  return WithPrecision(value, std::chars_format::scientific, decimals);
}

}  // namespace covopt
