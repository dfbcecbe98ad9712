#include "covopt/report/wrap_words.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

namespace covopt::report {

std::vector<std::string> WrapWords(std::string_view text, std::size_t width) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t space = text.find(' ', at);
    const std::string_view word =
        text.substr(at, space == std::string_view::npos ? std::string_view::npos : space - at);
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      lines.push_back(line);
      line.clear();
    }
    if (!word.empty()) {
      if (!line.empty()) line += ' ';
      line += word;
    }
    if (space == std::string_view::npos) break;
    at = space + 1;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

void PrintWrappedRow(std::ostream& out, std::string_view label, std::size_t label_width, std::string_view value,
                     std::size_t width) {
  const std::vector<std::string> lines = WrapWords(value, width);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    fmt::print(out, "  {:<{}} {}\n", i == 0 ? label : "", label_width, lines[i]);
  }
  if (lines.empty()) fmt::print(out, "  {}\n", label);
}

}  // namespace covopt::report
