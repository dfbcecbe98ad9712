#pragma once
/// @file trajectory_json.hpp
/// A trajectory safety check as JSON text: the object `covopt robot --trajectory --json`
/// prints and `covopt.check_trajectory()` returns as a dict (both call TrajectoryCheckJson).
/// SI values, units in the keys; an infinite (fixed) reflected mass is "fixed"; a speed limit
/// or scale that does not exist (no safe speed, at rest) is null.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/scene.hpp"
#include "covopt/optim/trajectory_check.hpp"
#include "covopt/robot/trajectory.hpp"

namespace covopt::report {

/// The per-sample keys in order, as the JSON samples' keys and the CSV header: time_s,
/// speed_m_per_s, reflected_mass_kg, moving, max_safe_speed_m_per_s, speed_scale,
/// limited_by, laceration_ratio, contusion_ratio, compression_ratio, safe.
/// max_safe_speed_m_per_s is the largest safe speed at the sample's reflected mass (null when
/// no speed is safe there; the 100 m/s ceiling when safe up to it, limited_by "none");
/// speed_scale = max safe speed / speed (null at rest); the ratios are those of the impact
/// at the sample's own speed (0 at rest); safe: those ratios pass the criterion.
std::span<const std::string_view> TrajectorySampleColumns() noexcept;

/// One sample's cells as text, in TrajectorySampleColumns order, for a CSV: numbers in
/// shortest round-trip form, "fixed" for an infinite mass, "true"/"false", "" for null.
std::vector<std::string> TrajectorySampleCsvCells(const optim::SampleVerdict& sample);

/// The check as one JSON object: status ("safe", "unsafe", "at-rest", "evaluation-failed"),
/// message, safe_speed_scale (null when at rest throughout or evaluation-failed), worst_sample
/// (null when at rest or evaluation-failed; else {index (0-based), then the sample's keys}),
/// sample_count, unsafe_sample_count, failed_sample_count (a failed sample's limit, scale,
/// ratios and safe are null), criterion,
/// safety_factor, limits (and the derated ones), search_limit {max_speed_m_per_s}, scene
/// (SceneJson of `scene` without the robot's mass and speed, which each sample brings, and
/// with covering.material: `covering_material`, the catalog name, or null),
/// joint_names (the trajectory's joint order, from `motion`), samples
/// (TrajectorySampleColumns), warnings: `input_warnings`, then the robot's (motion.warnings:
/// locked joints, fixed directions), then the check's.
/// `indent` as in nlohmann's dump: 2 (the CLI's), or -1 for one line.
std::string TrajectoryCheckJson(const optim::TrajectoryCheck& check, const robot::ContactMotionResult& motion,
                                const Scene& scene, const std::optional<std::string>& covering_material,
                                const optim::SpeedLimitOptions& options,
                                std::span<const std::string> input_warnings = {}, int indent = 2);

}  // namespace covopt::report
