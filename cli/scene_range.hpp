#pragma once
/// @file scene_range.hpp
/// A scene input given as a range, LO..HI (the sweep's range syntax, read by ParseRange): on
/// `simulate`, `optimize` and `speed-limit` it means "uncertain within [LO, HI]" (issue 14,
/// docs/model.md §11). A flag (`--head-mass 3.7kg..5.8kg`) or a scene-file string
/// (`mass = "3.7kg..5.8kg"` under [head]) may hold one; other commands refuse it.

#include <string>
#include <string_view>

#include "scene_fields.hpp"

namespace covopt::cli {

/// One scene field known only within [low, high].
struct SceneRange {
  std::string field;   ///< dotted name, "head.mass"
  std::string name;    ///< the field's name, "head-mass" (what --distribution NAME= takes)
  std::string text;    ///< as written, "3.7kg..5.8kg"
  std::string source;  ///< where: "--head-mass" or "scene.toml:4:8 (head.mass)"
  double low = 0.0;    ///< [SI]
  double high = 0.0;   ///< [SI], >= low
};

/// True when `text` is written as a range (holds "..").
bool IsRangeText(std::string_view text) noexcept;

/// Reads "LO..HI" for `field` (units as ParseQuantity reads them; both ends needed, finite,
/// LO <= HI). @param source names the value in messages ("--head-mass" or "file:line:col").
/// @throws InputError "--head-mass: a range needs finite ends: a fixed body cannot be
///   uncertain ... (got 'fixed..5kg')", "... the lower end is above the upper end ...".
SceneRange ParseSceneRange(std::string_view text, const SceneField& field, std::string_view source);

/// The message for a command that takes no ranges: "--head-mass '3.7kg..5.8kg': a range
/// (an uncertain input) is taken by simulate, optimize and speed-limit only; <command> needs
/// one value (<hint>)".
std::string RangeRefusal(const SceneRange& range, std::string_view command, std::string_view hint = {});

}  // namespace covopt::cli
