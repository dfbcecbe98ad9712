// What the scene-file library's TOML readers share (toml_input.hpp).
#include "toml_input.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>

#include "covopt/internal/text.hpp"
#include "covopt/internal/toml_text.hpp"

namespace covopt::scene_file::internal {

using covopt::internal::TypeName;
using covopt::internal::Where;

std::string ReadBoundedFile(const std::filesystem::path& path, std::string_view what, std::size_t max_bytes) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw std::invalid_argument(fmt::format("cannot read {} '{}': it is a directory", what, path.string()));
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    throw std::invalid_argument(fmt::format("cannot read {} '{}': {}", what, path.string(), std::strerror(errno)));
  }
  // At most max_bytes + 1 bytes are read, so /dev/zero or a huge file is refused at once
  // instead of filling the memory.
  std::string text;
  char buffer[65536];
  int error = 0;
  while (text.size() <= max_bytes) {
    const std::size_t want = std::min(sizeof buffer, max_bytes + 1 - text.size());
    const ssize_t n = ::read(fd, buffer, want);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) error = errno;
    if (n <= 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  if (error != 0) {
    throw std::invalid_argument(fmt::format("cannot read {} '{}': {}", what, path.string(), std::strerror(error)));
  }
  if (text.size() > max_bytes) {
    throw std::invalid_argument(fmt::format("cannot read {} '{}': larger than the limit of {} bytes{}", what,
                                            path.string(), max_bytes, max_bytes == (std::size_t{1} << 20) ? " (1 MiB)" : ""));
  }
  return text;
}

std::string NumberText(const toml::node& node) {
  if (node.is_integer()) return std::to_string(**node.as_integer());
  return fmt::format("{}", **node.as_floating_point());
}

std::string Shown(const toml::node& node) {
  if (node.is_string()) return fmt::format("'{}'", covopt::internal::EscapeControlCharacters(**node.as_string()));
  return NumberText(node);
}

double ReadQuantity(const toml::node& node, const QuantitySpec& spec, const std::string& name,
                    std::string_view example, std::string_view source) {
  const std::string where = Where(source, node.source());
  try {
    if (node.is_integer() || node.is_floating_point()) {
      const double value = node.is_integer() ? static_cast<double>(**node.as_integer())
                                             : **node.as_floating_point();
      if (!std::isfinite(value)) {
        throw std::invalid_argument(fmt::format("{}: not a finite number (got {})", name, value));
      }
      CheckBareNumber(value, NumberText(node), spec, name, "\"");
      return value;
    }
    if (node.is_string()) return ParseQuantity(**node.as_string(), spec, name);
  } catch (const std::invalid_argument& e) {  // ParseQuantity, CheckBareNumber, or not finite
    throw std::invalid_argument(fmt::format("{}: {}", where, e.what()));
  }
  throw std::invalid_argument(fmt::format(
      "{}: {}: expected a number (SI) or a string with a unit such as \"{}\", got {}", where,
      name, example, TypeName(node)));
}

}  // namespace covopt::scene_file::internal
