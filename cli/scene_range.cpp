#include "scene_range.hpp"

#include <fmt/format.h>

#include "errors.hpp"

namespace covopt::cli {

SceneRange ParseSceneRange(std::string_view text, const SceneField& field, std::string_view source) {
  return AsInputError([&] { return scene_file::ParseSceneRange(text, field, source); });
}

std::string RangeRefusal(const SceneRange& range, std::string_view command, std::string_view hint) {
  return fmt::format("{} '{}': a range (an uncertain input) is taken by simulate, optimize and speed-limit only; "
                     "{} needs one value{}{}",
                     range.source, range.text, command, hint.empty() ? "" : "; ", hint);
}

}  // namespace covopt::cli
