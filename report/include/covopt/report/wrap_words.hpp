#pragma once
/// @file wrap_words.hpp
/// Long values of the readable reports broken into lines.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace covopt::report {

/// `text` broken at spaces into lines of at most `width` characters (longer words, such as
/// URLs, stay whole): how `materials show` and `body-regions show` wrap long values.
std::vector<std::string> WrapWords(std::string_view text, std::size_t width);

}  // namespace covopt::report
