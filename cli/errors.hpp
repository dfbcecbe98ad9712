#pragma once
/// @file errors.hpp
/// The two kinds of failure the CLI tells apart by exit code (besides a failed computation).
///
///     InputError   bad input: a flag, a value, a scene file          -> exit 2
///     OutputError  the answer is fine but an output could not be written
///                  (history CSV, plot, gnuplot missing)              -> exit 1

#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "covopt/internal/text.hpp"
#include "covopt/report/output_file.hpp"

namespace covopt::cli {

/// Bad input. The message names the flag or scene-file field and the offending value.
class InputError : public std::invalid_argument {
 public:
  explicit InputError(const std::string& message) : std::invalid_argument(message) {}
};

/// Calls `f` and returns what it returns, with the library's bad-input std::invalid_argument
/// (a scene file, a range, a limit) rethrown as InputError with the same message.
template <class F>
decltype(auto) AsInputError(F&& f) {
  try {
    return std::forward<F>(f)();
  } catch (const InputError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

/// An output file or an external tool failed (exit 1): the library's (covopt/report/output_file.hpp).
using report::OutputError;

/// A message with every overlong word (a run of 200+ bytes without a space: a
/// 100,000-digit value, a pasted file) shown as its first 60 bytes (not cutting a UTF-8
/// character), "…" and its length, and every control character (a line break, a tab, an
/// escape sequence, a NUL) shown escaped as C writes it (`\n`, `\t`, `\0`, `\x1b`), so that an
/// error stays one readable line whatever value it echoes. The quantity parser shortens and
/// escapes the values it echoes the same way (core/src/quantity.cpp); this catches every
/// other echo (a link name, a path), since every CLI error line goes through it.
inline std::string ShortenLongWords(std::string_view raw_message) {
  constexpr std::size_t kLong = 200, kKept = 60;
  const std::string escaped = covopt::internal::EscapeControlCharacters(raw_message);
  const std::string_view message = escaped;
  std::string shortened;
  std::size_t i = 0;
  while (i < message.size()) {
    std::size_t end = i;
    while (end < message.size() && message[end] != ' ') ++end;
    const std::string_view word = message.substr(i, end - i);
    if (word.size() < kLong) {
      shortened += word;
    } else {
      std::size_t keep = kKept;
      while (keep > 0 && (static_cast<unsigned char>(word[keep]) & 0xC0) == 0x80) --keep;
      shortened += std::string(word.substr(0, keep)) + "… (" + std::to_string(word.size()) +
                   " characters)";
    }
    if (end < message.size()) shortened += ' ';
    i = end + 1;
  }
  return shortened;
}

/// A subcommand's error exits: one line "covopt <command>: error: <message>" on `err`, and
/// the exit code to return (BadInput 2, Failed 1).
class CommandErrors {
 public:
  CommandErrors(std::ostream& err, std::string command) : err_(err), command_(std::move(command)) {}
  int BadInput(std::string_view message) const { return Print(message, 2); }
  int Failed(std::string_view message) const { return Print(message, 1); }
  /// The one-line message, then the tool's own lines (OutputError::details), each on a line
  /// of its own prefixed "  <tool>: " and escaped as the message is.
  int Failed(const OutputError& error) const {
    Print(error.what(), 1);
    for (const std::string& line : error.details()) err_ << "  " << error.tool() << ": " << ShortenLongWords(line) << '\n';
    return 1;
  }

 private:
  int Print(std::string_view message, int exit_code) const {
    err_ << "covopt " << command_ << ": error: " << ShortenLongWords(message) << '\n';
    return exit_code;
  }
  std::ostream& err_;
  std::string command_;
};

}  // namespace covopt::cli
