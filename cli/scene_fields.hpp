#pragma once
/// @file scene_fields.hpp
/// The numeric fields of covopt::Scene a user can set, as the command line sees them: the
/// library's table (covopt/core/scene_fields.hpp), each with its flag ("--" + name:
/// `--robot-mass`). The threshold reading (`--thresholds`) and the injury limits and safety
/// factor (`--laceration-limit` ...) are read with the scene-file library's checks
/// (covopt/scene_file/fields.hpp), here throwing the CLI's InputError.

#include <span>
#include <string>
#include <string_view>

#include "covopt/core/scene.hpp"
#include "covopt/core/scene_fields.hpp"
#include "covopt/scene_file/fields.hpp"
#include "covopt/scene_file/scene_inputs.hpp"
#include "quantity.hpp"

namespace covopt::cli {

/// One settable numeric field of a Scene (table, key, name, spec, field, help: see
/// covopt::SceneField) and its command-line flag.
struct SceneField : covopt::SceneField {
  std::string_view flag;  ///< "--" + name, e.g. "--robot-mass"
};

/// Every settable numeric field, in the order of `covopt simulate --help` (that of
/// covopt::SceneFields()).
std::span<const SceneField> SceneFields() noexcept;

using scene_file::kMaxSafetyFactor;
using scene_file::SceneTables;
using scene_file::ThresholdsName;

/// One injury limit, or the safety factor (key, name, spec, help: see
/// covopt::scene_file::LimitField) and its command-line flag.
struct LimitField : scene_file::LimitField {
  std::string_view flag;  ///< "--" + name: "--laceration-limit", "--safety-factor"
};

/// laceration [Pa], contusion [J/m²], safety_factor [-], in this order.
std::span<const LimitField> LimitFields() noexcept;

/// scene_file::CheckLimitValue, throwing InputError.
/// @throws InputError "--safety-factor must be in [1, 100] (got '0.5')".
void CheckLimitValue(const LimitField& field, double value, std::string_view name,
                     std::string_view shown);

/// The library's one resolution of scene inputs (scene_file::ApplySceneInputs) for inputs
/// typed as flags, its messages naming the flags (the CLI's one table of their spellings,
/// scene_file::SceneInputSpellings).
/// @throws InputError "--robot-radius 40: a bare number is in metres ...".
void ApplySceneFlagInputs(std::span<const scene_file::SceneInput> inputs, scene_file::ResolvedScene& resolved);

/// scene_file::ParseThresholds ("cumulative" or "literal"), throwing InputError.
ThresholdReading ParseThresholds(std::string_view text, std::string_view name);

/// covopt::ParseHeadAreaOrThrow (frontal, temporo-parietal, nasal, ...), throwing InputError.
/// @throws InputError "--head-area must be one of frontal, ... (got \"cheek\")".
HeadArea ParseHeadArea(std::string_view text, std::string_view name);

}  // namespace covopt::cli
