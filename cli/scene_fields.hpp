#pragma once
/// @file scene_fields.hpp
/// The numeric fields of covopt::Scene a user can set, listed once for the command line
/// (`--robot-mass`) and the scene file (`[robot] mass`), so both read values the same way.
/// The threshold reading (`--thresholds`, `[model] thresholds`) is a word, not a quantity,
/// and is handled beside this table.

#include <span>
#include <string>
#include <string_view>

#include "covopt/core/scene.hpp"
#include "quantity.hpp"

namespace covopt::cli {

/// One settable numeric field of a Scene.
struct SceneField {
  std::string_view table;     ///< scene-file table, e.g. "robot"
  std::string_view key;       ///< key in that table, e.g. "mass"
  std::string_view flag;      ///< command-line flag, e.g. "--robot-mass"
  QuantitySpec spec;          ///< kind, and whether "fixed"/"flat" are allowed
  double& (*field)(Scene&);   ///< the Scene member it sets
  std::string_view help;      ///< one line for --help

  /// "robot.mass": how the scene file and messages name the field.
  std::string dotted_name() const;
};

/// Every settable numeric field, in the order of `covopt simulate --help`.
std::span<const SceneField> SceneFields() noexcept;

/// The scene-file tables, in order: robot, covering, head, scalp, skull, model.
std::span<const std::string_view> SceneTables() noexcept;

/// Parses a threshold reading: "cumulative" or "literal" (case-sensitive).
/// @throws InputError naming `name` and the accepted words.
ThresholdReading ParseThresholds(std::string_view text, std::string_view name);

/// "cumulative" or "literal" (the CLI's own spelling, independent of core's ToString).
std::string_view ThresholdsName(ThresholdReading reading) noexcept;

}  // namespace covopt::cli
