#include "text.hpp"

#include <array>
#include <charconv>

namespace covopt::materials::internal {

std::string FormatNumber(double value) {
  std::array<char, 64> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  if (ec != std::errc{}) return "?";
  return std::string(buffer.data(), end);
}

std::string JoinAlternatives(const std::vector<std::string>& words, bool quote) {
  std::string joined;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) joined += (i + 1 == words.size()) ? " or " : ", ";
    joined += quote ? "'" + words[i] + "'" : words[i];
  }
  return joined;
}

}  // namespace covopt::materials::internal
