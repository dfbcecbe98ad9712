#pragma once
/// @file retime_inputs.hpp
/// The inputs of `covopt retime` and covopt.retime() that are no plain values: the joints'
/// limits given as one value for every joint or one per joint, the thickness grid of the
/// cycle-time sweep, and the sweep's designs (a catalog material each, and the per-link
/// design). The CLI and Python call these, so both read the same input the same way.
///
///     const auto accel = covopt::audit::JointLimitVector({10.0}, 7, "--joint-accel-limit");
///     const auto grid = covopt::audit::ThicknessGrid("0..40mm:9", "--thickness");

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include <covopt/materials/catalog.hpp>

#include "covopt/audit/assemble.hpp"
#include "covopt/audit/retime.hpp"

namespace covopt::audit {

/// The largest joint limits a bare number may give (SI, rad or m): beyond them it is surely
/// another unit.
inline constexpr double kMaxJointSpeedLimit = 1e3;         ///< [rad/s or m/s]
inline constexpr double kMaxJointAccelerationLimit = 1e5;  ///< [rad/s² or m/s²]

/// A joint limit per joint from `values`: one value (for every joint) or one per joint, each
/// in (0, `max`], or +inf when `allow_infinite` (no limit).
/// @throws std::invalid_argument naming `field`, the joint and the value: a count neither 1 nor
///         `joint_count`, a value NaN, <= 0, above `max` or infinite where not allowed.
Eigen::VectorXd JointLimitVector(std::span<const double> values, std::size_t joint_count, std::string_view field,
                                 double max, bool allow_infinite);

/// The covering thicknesses [m] of `spec` ("0..40mm:9", "0,5mm,10mm": a sweep axis' spec,
/// scene_file::ParseSweepAxis of the covering thickness), sorted, each once.
/// @throws std::invalid_argument naming `field` and the text: a spec the reader refuses, a
///         thickness outside the covering thickness' range, fewer than 2 values.
std::vector<double> ThicknessGrid(std::string_view spec, std::string_view field);

/// The designs of the cycle-time sweep: one per material of `material_names` (looked up in
/// `catalog`, its law auto: a measured curve takes the foam law; every link wears it), or,
/// without names, the covering `assembled` gives every link (named by its material, or
/// "covering E = ... MPa"); then, when `per_link_design`, the per-link design
/// (assembled.options.design: its materials, thickness range and rule).
/// @throws std::invalid_argument naming `materials_field` for a material not in the catalog.
std::vector<CycleTimeDesign> CycleTimeDesigns(const AssembledAudit& assembled, const materials::Catalog& catalog,
                                              std::span<const std::string> material_names, bool per_link_design,
                                              std::string_view materials_field);

}  // namespace covopt::audit
