#pragma once
/// @file speed_limit_json.hpp
/// Speed (or mass) limits as JSON text: the object `covopt speed-limit --json` prints and
/// `covopt.speed_limit()` returns as a dict; both call SpeedLimitJson. SI values, units in the
/// keys; an infinite mass is "fixed"; a limit that does not exist (no safe value, or a failed
/// evaluation) is null.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/scene.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "covopt/optim/speed_limit_table.hpp"

namespace covopt::report {

using optim::SpeedLimitQuantity;
using optim::SpeedLimitRow;

/// The rows' column names in order, as the JSON rows' keys and the CSV header:
///   speed: material, robot_mass_kg, max_safe_speed_m_per_s, limited_by, laceration_ratio,
///          contusion_ratio, compression_ratio, status
///   mass:  material, speed_m_per_s, max_safe_mass_kg, limited_by, laceration_ratio,
///          contusion_ratio, compression_ratio, status
/// The ratios are those of the impact at the limit (at the search ceiling when safe up to it;
/// at the bottom of the range when nothing is safe).
std::span<const std::string_view> SpeedLimitColumns(SpeedLimitQuantity quantity) noexcept;

/// One row's cells as text, in SpeedLimitColumns order, for a CSV: numbers in shortest
/// round-trip form, "fixed" for an infinite mass, "" for null (no material, no safe value).
std::vector<std::string> SpeedLimitCsvCells(SpeedLimitQuantity quantity, const SpeedLimitRow& row);

/// The table as one JSON object: solve_for, criterion, safety_factor, limits (and the derated
/// ones), search_limit ({max_speed_m_per_s} or {max_mass_kg}), oracle ({name, reason, method,
/// rtol, evaluations, failed_evaluations, first_failure: optim::SpeedLimitOracle; search:
/// "penetration-axis" or "bracketed-bisection"}), rows (SpeedLimitColumns; a
/// limit that does not exist is null, "limited_by" "none" when safe up to the ceiling),
/// scene (SceneJson of `scene` without the quantity solved for, and without the one the rows
/// vary unless all rows share it; without the covering's modulus and Poisson ratio when the
/// rows are of several materials), warnings: `input_warnings`, then one per row that is safe
/// up to the search ceiling or has no safe value, saying so.
/// `indent` as in nlohmann's dump: 2 (the CLI's), or -1 for one line.
std::string SpeedLimitJson(SpeedLimitQuantity quantity, const Scene& scene,
                           const optim::SpeedLimitOptions& options, std::span<const SpeedLimitRow> rows,
                           std::span<const std::string> input_warnings = {}, int indent = 2);

/// The warnings SpeedLimitJson adds about the rows (one per row safe up to the ceiling or
/// without a safe value), for a table printed without JSON.
std::vector<std::string> SpeedLimitRowWarnings(SpeedLimitQuantity quantity, std::span<const SpeedLimitRow> rows);

}  // namespace covopt::report
