#include "covopt/scene_file/range.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "covopt/internal/text.hpp"

namespace covopt::scene_file {
namespace {

using internal::TrimBlanks;

std::string_view ExampleRange(const QuantitySpec& spec) {
  switch (spec.kind) {
    case QuantityKind::kModulus: return "10MPa..100MPa";
    case QuantityKind::kDensity: return "20kg/m3..60kg/m3";
    default: return "0.2..0.3";
  }
}

}  // namespace

bool IsRangeText(std::string_view text) noexcept { return text.find("..") != std::string_view::npos; }

materials::Range ParseQuantityRange(std::string_view text, const QuantitySpec& spec,
                                    std::string_view name, std::string_view example) {
  const std::string_view s = TrimBlanks(text);
  const auto fail = [&](std::string_view problem) {
    throw std::invalid_argument(fmt::format("{}: {} (got '{}')", name, problem, text));
  };
  if (example.empty()) example = ExampleRange(spec);
  const auto dots = s.find("..");
  if (dots == std::string_view::npos) {
    fail(fmt::format("expected a range LO..HI, LO.. or ..HI, e.g. {}", example));
  }
  const std::string_view low = TrimBlanks(s.substr(0, dots));
  const std::string_view high = TrimBlanks(s.substr(dots + 2));
  if (low.empty() && high.empty()) fail(fmt::format("give at least one end, e.g. {}", example));
  if ((!high.empty() && high.front() == '.') || (!low.empty() && low.back() == '.')) {
    fail(fmt::format("malformed range; write LO..HI, e.g. {}", example));
  }

  // The ends' units first (a bare end beside one with a unit is the likelier slip), then, at
  // the end, whether a bare end is plausible for the quantity.
  const QuantitySpec units_only{spec.kind, spec.allow_fixed, spec.allow_flat};
  materials::Range range;
  if (!low.empty()) range.min = ParseQuantity(low, units_only, name);
  if (!high.empty()) range.max = ParseQuantity(high, units_only, name);

  if (spec.kind != QuantityKind::kDimensionless && !low.empty() && !high.empty()) {
    const auto bare = [](std::string_view end) {
      const char c = end.back();
      return (c >= '0' && c <= '9') || c == '.';
    };
    const bool low_bare = bare(low) && *range.min != 0.0;
    const bool high_bare = bare(high) && *range.max != 0.0;
    if ((low_bare && !bare(high)) || (high_bare && !bare(low))) {
      fail(fmt::format("give the unit on both ends, e.g. {}; a bare number is SI", example));
    }
  }
  if (range.min && range.max && *range.min > *range.max) {
    fail("the lower end is above the upper end");
  }
  if (!low.empty()) ParseQuantity(low, spec, name);
  if (!high.empty()) ParseQuantity(high, spec, name);
  return range;
}

SceneRange ParseSceneRange(std::string_view text, const SceneField& field, std::string_view source) {
  const auto fail = [&](std::string_view problem) {
    throw std::invalid_argument(fmt::format("{}: {} (got '{}')", source, problem, text));
  };
  const std::string_view finite_ends =
      field.spec.allow_flat
          ? "a range needs finite ends: a flat robot cannot be uncertain; give a radius range, e.g. 20mm..100mm"
          : "a range needs finite ends: a fixed body cannot be uncertain; give a mass range, e.g. 3.7kg..5.8kg";
  // 'fixed' and 'flat' first: ParseQuantityRange would read them as +inf and call the order
  // wrong.
  if (text.find("fixed") != std::string_view::npos || text.find("flat") != std::string_view::npos) {
    fail(finite_ends);
  }
  const materials::Range range = ParseQuantityRange(text, field.spec, source);
  if (!range.min || !range.max) fail("an uncertain input needs both ends, LO..HI");
  if (!std::isfinite(*range.min) || !std::isfinite(*range.max)) fail(finite_ends);
  SceneRange parsed;
  parsed.field = field.dotted_name();
  parsed.name = std::string(field.name);
  parsed.text = std::string(text);
  parsed.source = std::string(source);
  parsed.low = *range.min;
  parsed.high = *range.max;
  return parsed;
}

}  // namespace covopt::scene_file
