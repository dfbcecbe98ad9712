#pragma once
/// @file scene_fields.hpp
/// The numeric fields of covopt::Scene a user can set, as the command line and scene files
/// see them: the library's table (covopt/core/scene_fields.hpp), each with its flag
/// ("--" + name: `--robot-mass`) beside its scene-file table and key (`[robot] mass`), so
/// both read values the same way. The threshold reading (`--thresholds`, `[model]
/// thresholds`) is a word, not a quantity, and is handled beside this table. The injury
/// limits and the safety factor (`[limits]`, `--laceration-limit` ...) are not Scene fields;
/// they have their own table, LimitFields().

#include <span>
#include <string>
#include <string_view>

#include "covopt/core/scene.hpp"
#include "covopt/core/scene_fields.hpp"
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

/// The scene-file tables, in order: robot, covering, head, scalp, skull, model, limits.
std::span<const std::string_view> SceneTables() noexcept;

/// One injury limit, or the safety factor: a key of the scene file's [limits] table and its
/// flag. Values are checked by CheckLimitValue.
struct LimitField {
  std::string_view key;   ///< key in [limits]: "laceration", "contusion", "safety_factor"
  std::string_view flag;  ///< "--laceration-limit", "--contusion-limit", "--safety-factor"
  QuantitySpec spec;      ///< quantity_specs::kLacerationLimit ...
  std::string_view help;  ///< one line for --help

  /// "limits.laceration": how the scene file and messages name it.
  std::string dotted_name() const;
};

/// laceration [Pa], contusion [J/m²], safety_factor [-], in this order.
std::span<const LimitField> LimitFields() noexcept;

/// Checks a value read (in SI) for a limit field: an injury limit must be > 0, the safety
/// factor in [1, kMaxSafetyFactor].
/// @param name the flag or "limits.KEY"; @param shown the value as written, for the message.
/// @throws InputError "limits.safety_factor must be in [1, 100] (got 0.5)".
void CheckLimitValue(const LimitField& field, double value, std::string_view name,
                     std::string_view shown);

/// The largest safety factor accepted (optimize's --safety-factor has the same bound).
inline constexpr double kMaxSafetyFactor = 100.0;

/// Parses a threshold reading: "cumulative" or "literal" (case-sensitive).
/// @throws InputError naming `name` and the accepted words.
ThresholdReading ParseThresholds(std::string_view text, std::string_view name);

/// "cumulative" or "literal" (the CLI's own spelling, independent of core's ToString).
std::string_view ThresholdsName(ThresholdReading reading) noexcept;

}  // namespace covopt::cli
