#include "scene_range.hpp"

#include <cmath>

#include <fmt/format.h>

#include "errors.hpp"
#include "materials_command.hpp"

namespace covopt::cli {

bool IsRangeText(std::string_view text) noexcept { return text.find("..") != std::string_view::npos; }

SceneRange ParseSceneRange(std::string_view text, const SceneField& field, std::string_view source) {
  const auto fail = [&](std::string_view problem) {
    throw InputError(fmt::format("{}: {} (got '{}')", source, problem, text));
  };
  // 'fixed' and 'flat' first: ParseRange would read them as +inf and call the order wrong.
  if (text.find("fixed") != std::string_view::npos || text.find("flat") != std::string_view::npos) {
    fail(field.spec.allow_flat
             ? "a range needs finite ends: a flat robot cannot be uncertain; give a radius range, e.g. 20mm..100mm"
             : "a range needs finite ends: a fixed body cannot be uncertain; give a mass range, e.g. 3.7kg..5.8kg");
  }
  const materials::Range range = ParseRange(text, field.spec, source);
  if (!range.min || !range.max) fail("an uncertain input needs both ends, LO..HI");
  if (!std::isfinite(*range.min) || !std::isfinite(*range.max)) {
    fail(field.spec.allow_flat
             ? "a range needs finite ends: a flat robot cannot be uncertain; give a radius range, e.g. 20mm..100mm"
             : "a range needs finite ends: a fixed body cannot be uncertain; give a mass range, e.g. 3.7kg..5.8kg");
  }
  SceneRange parsed;
  parsed.field = field.dotted_name();
  parsed.name = std::string(field.name);
  parsed.text = std::string(text);
  parsed.source = std::string(source);
  parsed.low = *range.min;
  parsed.high = *range.max;
  return parsed;
}

std::string RangeRefusal(const SceneRange& range, std::string_view command, std::string_view hint) {
  return fmt::format("{} '{}': a range (an uncertain input) is taken by simulate, optimize and speed-limit only; "
                     "{} needs one value{}{}",
                     range.source, range.text, command, hint.empty() ? "" : "; ", hint);
}

}  // namespace covopt::cli
