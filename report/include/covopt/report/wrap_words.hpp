#pragma once
/// @file wrap_words.hpp
/// Long values of the readable reports broken into lines.

#include <cstddef>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace covopt::report {

/// `text` broken at spaces into lines of at most `width` characters (longer words, such as
/// URLs, stay whole): how `materials show` and `body-regions show` wrap long values.
std::vector<std::string> WrapWords(std::string_view text, std::size_t width);

/// A "  label   value" row of a `show` listing: the label padded to `label_width`, `value`
/// wrapped at `width` (WrapWords) with its further lines under the first; the bare label when
/// `value` is empty.
void PrintWrappedRow(std::ostream& out, std::string_view label, std::size_t label_width, std::string_view value,
                     std::size_t width);

}  // namespace covopt::report
