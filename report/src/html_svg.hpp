#pragma once
/// @file html_svg.hpp
/// A chart's SVG document made fit to inline in a report (private to covopt_report).

#include <cstddef>
#include <string>
#include <string_view>

namespace covopt::internal {

/// `svg` (a standalone SVG document, gnuplot's) as an inline `<svg>` element: everything before
/// the root `<svg` (XML prolog, DOCTYPE, comments) and after its end dropped; every `id`
/// prefixed with `prefix`, and every local reference to one (`href="#x"`, `xlink:href='#x'`,
/// `url(#x)`) rewritten to match, so that several charts' ids stay unique in one document;
/// `<script>` elements and `on*` event attributes removed. The rest of the text is kept as it is.
/// @throws std::invalid_argument naming chart `number` when it has no `<svg>` root, a tag is
///         not closed, or it refers to anything outside itself (an external href or url()).
std::string InlineSvg(std::string_view svg, std::string_view prefix, std::size_t number);

}  // namespace covopt::internal
