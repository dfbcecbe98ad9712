#pragma once
/// @file text.hpp
/// Private text helpers shared by covopt's readers of user input (the materials catalog, scene
/// files, the CLI's flag suggestions, the quantity parser, the trajectory reader): ASCII case
/// folding, the edit distance, the "did you mean" candidate, and the escaping of control
/// characters in echoed values. Header-only and not installed: target covopt_text_internal, linked
/// PRIVATE (at build time only) by covopt_materials, covopt_scene_file and the CLI.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace covopt::internal {

/// `text` without leading and trailing spaces and tabs.
constexpr std::string_view TrimBlanks(std::string_view text) noexcept {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

/// ASCII lower case of one character.
constexpr char LowerChar(char c) noexcept {
  return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

/// ASCII lower case (names are compared ignoring ASCII case only).
inline std::string Lower(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) c = LowerChar(c);
  return lower;
}

/// a == b ignoring ASCII case.
inline bool EqualsIgnoringCase(std::string_view a, std::string_view b) noexcept {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(),
                    [](char x, char y) { return LowerChar(x) == LowerChar(y); });
}

/// Levenshtein distance (insertions, deletions, substitutions), byte-wise.
inline std::size_t EditDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// `text` with every control character (below 0x20, and DEL) escaped as C writes it: a line
/// break as `\n`, a carriage return `\r`, a tab `\t`, a NUL `\0`, any other as `\xHH`. Every
/// message that echoes a user's value (a flag's value, a link or material name, a file's cell,
/// a path) echoes it through this, so that the message stays one line and is not cut at a NUL
/// (std::exception::what() ends at the first NUL).
inline std::string EscapeControlCharacters(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f) {
      escaped += c;
      continue;
    }
    switch (c) {
      case '\n': escaped += "\\n"; break;
      case '\r': escaped += "\\r"; break;
      case '\t': escaped += "\\t"; break;
      case '\0': escaped += "\\0"; break;
      default: {
        constexpr char kHex[] = "0123456789abcdef";
        escaped += "\\x";
        escaped += kHex[byte >> 4];
        escaped += kHex[byte & 0xf];
      }
    }
  }
  return escaped;
}

/// The edit distance up to which `word` is taken for a typo: max(2, |word| / 3).
inline std::size_t TypoTolerance(std::string_view word) noexcept {
  return std::max<std::size_t>(2, word.size() / 3);
}

/// The candidate closest to `word` (ignoring ASCII case; the first of equally close ones) if
/// it is within TypoTolerance(word).
inline std::optional<std::string_view> Closest(std::string_view word,
                                               const std::vector<std::string_view>& candidates) {
  const std::string lower = Lower(word);
  std::optional<std::string_view> best;
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  for (const std::string_view candidate : candidates) {
    const std::size_t d = EditDistance(lower, Lower(candidate));
    if (d < best_distance) {
      best_distance = d;
      best = candidate;
    }
  }
  if (best && best_distance <= TypoTolerance(word)) return best;
  return std::nullopt;
}


}  // namespace covopt::internal
