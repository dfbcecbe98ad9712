#pragma once
/// @file fields.hpp
/// What a scene file holds besides covopt's Scene fields (covopt/core/scene_fields.hpp): its
/// tables, the injury limits and safety factor of [limits], and the threshold reading of
/// [model]. The command line and Python name the same values ("--laceration-limit",
/// `laceration_limit`), so all three read them with these checks and messages.

#include <span>
#include <string>
#include <string_view>

#include "covopt/core/quantity.hpp"
#include "covopt/core/scene.hpp"

namespace covopt::scene_file {

/// The scene-file tables, in order: robot, covering, head, scalp, skull, model, limits, report.
std::span<const std::string_view> SceneTables() noexcept;

/// The keys of a report's sign-off settings, the scene file's [report] table and Python's
/// report_info: project, cell, assessor, note, margin_threshold, appendix
/// (covopt/report/report_settings.hpp reads them).
std::span<const std::string_view> ReportKeys() noexcept;

/// One injury limit, or the safety factor: a key of the scene file's [limits] table.
struct LimitField {
  std::string_view key;   ///< key in [limits]: "laceration", "contusion", "safety_factor"
  /// The value's name: "laceration-limit". The command-line flag is "--" + name, the Python
  /// keyword the name with '_' for '-'.
  std::string_view name;
  QuantitySpec spec;      ///< quantity_specs::kLacerationLimit ...
  std::string_view help;  ///< one line for help texts

  /// "limits.laceration": how the scene file and messages name it.
  std::string dotted_name() const;
};

/// laceration [Pa], contusion [J/m²], safety_factor [-], in this order.
std::span<const LimitField> LimitFields() noexcept;

/// The largest safety factor accepted [-].
inline constexpr double kMaxSafetyFactor = 100.0;

/// Checks a value read (in SI) for a limit field: an injury limit must be > 0, the safety
/// factor in [1, kMaxSafetyFactor].
/// @param name the flag or "limits.KEY"; @param shown the value as written, for the message.
/// @throws std::invalid_argument "limits.safety_factor must be in [1, 100] (got 0.5)".
void CheckLimitValue(const LimitField& field, double value, std::string_view name,
                     std::string_view shown);

/// Parses a threshold reading: "cumulative" or "literal" (case-sensitive).
/// @throws std::invalid_argument naming `name` and the accepted words.
ThresholdReading ParseThresholds(std::string_view text, std::string_view name);

/// "cumulative" or "literal": the spelling scene files and the command line use.
std::string_view ThresholdsName(ThresholdReading reading) noexcept;

/// Reads the covering law: "auto", "foam" or "hertz" (covopt::ParseCoveringLaw).
/// @param name how messages call the value ("covering.law", "--covering-law").
/// @throws std::invalid_argument "covering.law: expected 'auto', 'foam' or 'hertz' (got 'soft')".
CoveringLaw ParseCoveringLawOrThrow(std::string_view text, std::string_view name);

}  // namespace covopt::scene_file
