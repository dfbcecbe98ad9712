#pragma once
/// @file scene_range.hpp
/// A scene input given as a range, LO..HI (covopt/scene_file/range.hpp): on `simulate`,
/// `optimize` and `speed-limit` it means "uncertain within [LO, HI]" (issue 14, docs/model.md
/// §11). A flag (`--head-mass 3.7kg..5.8kg`) or a scene-file string (`mass = "3.7kg..5.8kg"`
/// under [head]) may hold one; other commands refuse it.

#include <string>
#include <string_view>

#include "covopt/scene_file/range.hpp"
#include "scene_fields.hpp"

namespace covopt::cli {

using scene_file::IsRangeText;
using scene_file::SceneRange;

/// scene_file::ParseSceneRange for a flag, throwing InputError.
/// @throws InputError "--head-mass: a range needs finite ends: ... (got 'fixed..5kg')".
SceneRange ParseSceneRange(std::string_view text, const SceneField& field, std::string_view source);

/// The message for a command that takes no ranges: "--head-mass '3.7kg..5.8kg': a range
/// (an uncertain input) is taken by simulate, optimize and speed-limit only; <command> needs
/// one value (<hint>)".
std::string RangeRefusal(const SceneRange& range, std::string_view command, std::string_view hint = {});

}  // namespace covopt::cli
