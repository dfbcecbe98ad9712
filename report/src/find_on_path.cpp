// The search of $PATH for a program (gnuplot for the charts, Chromium for the PDF report).
#include "covopt/report/find_on_path.hpp"

#include <cstdlib>
#include <string>
#include <system_error>

#include <unistd.h>

namespace covopt::report {

std::optional<std::filesystem::path> FindOnPath(std::string_view name) {
  const char* const path_variable = std::getenv("PATH");
  if (path_variable == nullptr) return std::nullopt;
  std::string_view directories = path_variable;
  while (true) {
    const std::size_t colon = directories.find(':');
    const std::string_view directory = directories.substr(0, colon);
    // An empty entry means the current directory (POSIX).
    const std::filesystem::path candidate =
        std::filesystem::path(directory.empty() ? "." : std::string(directory)) / name;
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0) {
      return candidate;
    }
    if (colon == std::string_view::npos) break;
    directories.remove_prefix(colon + 1);
  }
  return std::nullopt;
}

}  // namespace covopt::report
