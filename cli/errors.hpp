#pragma once
/// @file errors.hpp
/// The two kinds of failure the CLI tells apart by exit code (besides a failed computation).
///
///     InputError   bad input: a flag, a value, a scene file          -> exit 2
///     OutputError  the answer is fine but an output could not be written
///                  (history CSV, plot, gnuplot missing)              -> exit 1

#include <stdexcept>
#include <string>

namespace covopt::cli {

/// Bad input. The message names the flag or scene-file field and the offending value.
class InputError : public std::invalid_argument {
 public:
  explicit InputError(const std::string& message) : std::invalid_argument(message) {}
};

/// An output file or an external tool failed. The message names the file or the tool.
class OutputError : public std::runtime_error {
 public:
  explicit OutputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace covopt::cli
