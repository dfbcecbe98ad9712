#pragma once
// Small text helpers of covopt::materials (private): ASCII case folding, edit distance and
// "did you mean" candidates, number formatting for messages.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace covopt::materials::internal {

/// ASCII lower case (names are compared ignoring ASCII case only).
std::string Lower(std::string_view text);

/// a == b ignoring ASCII case.
bool EqualsIgnoringCase(std::string_view a, std::string_view b) noexcept;

/// Levenshtein distance (insertions, deletions, substitutions), byte-wise.
std::size_t EditDistance(std::string_view a, std::string_view b);

/// The edit distance up to which `word` is taken for a typo: max(2, |word| / 3).
std::size_t TypoTolerance(std::string_view word) noexcept;

/// The candidate closest to `word` (ignoring case) if it is within TypoTolerance.
std::optional<std::string_view> Closest(std::string_view word,
                                        const std::vector<std::string_view>& candidates);

/// A number for messages: shortest form that reads back the same (e.g. 0.5, 2.76e+07).
std::string FormatNumber(double value);

/// "a, b or c" (each quoted with 'q' when quote is true).
std::string JoinAlternatives(const std::vector<std::string>& words, bool quote);

}  // namespace covopt::materials::internal
