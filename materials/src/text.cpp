#include "text.hpp"

#include <covopt/core/number_format.hpp>

namespace covopt::materials::internal {

std::string FormatNumber(double value) { return FormatShortest(value); }

std::string JoinAlternatives(const std::vector<std::string>& words, bool quote) {
  std::string joined;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) joined += (i + 1 == words.size()) ? " or " : ", ";
    joined += quote ? "'" + words[i] + "'" : words[i];
  }
  return joined;
}

}  // namespace covopt::materials::internal
