#pragma once
/// @file body_region_trajectory.hpp
/// A robot's motion judged against ISO/TS 15066 body regions (docs/model.md §13): per sample,
/// the body contact at the sample's contact speed and reflected mass against every region
/// named (JudgeBodyContact), and the largest safe speed at that mass (MaxSafeSpeed); the
/// trajectory's safe speed scale is the smallest max safe speed / speed over the moving
/// samples and the regions. The counterpart of CheckTrajectory (trajectory_check.hpp), which
/// judges the head.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <covopt/core/body_contact.hpp>
#include <covopt/materials/body_regions.hpp>

#include "covopt/optim/body_region_check.hpp"
#include "covopt/optim/trajectory_check.hpp"

namespace covopt::optim {

/// The verdict at one sample, over every region.
struct BodyRegionSampleVerdict {
  double time_s = 0.0;             ///< [s]
  double speed_m_per_s = 0.0;      ///< [m/s]
  double reflected_mass_kg = 0.0;  ///< [kg] (+inf: fixed)
  /// False at rest (speed < 1e-6 m/s): no contact, ratios 0, no limit on the scale.
  bool moving = false;
  /// The largest governing ratio over the regions (unscaled) [-], its limit and its region.
  double worst_ratio = 0.0;
  BodyLimitKind binding = BodyLimitKind::kNone;
  std::size_t worst_region = 0;  ///< index into the regions given
  /// Every region admissible at this sample.
  bool safe = true;
  /// The smallest max safe speed over the regions at this mass [m/s], and its region.
  double max_safe_speed_m_per_s = 0.0;
  std::size_t limiting_region = 0;  ///< index into the regions given
  BodyLimitKind limited_by = BodyLimitKind::kNone;
  /// max safe speed / speed [-]; +inf at rest.
  double speed_scale = 0.0;
};

/// The answer of CheckTrajectoryForBodyRegions.
struct BodyRegionTrajectoryCheck {
  TrajectoryCheckStatus status = TrajectoryCheckStatus::kAtRest;  ///< safe, unsafe or at-rest
  std::vector<BodyRegionSampleVerdict> samples;
  /// min over the moving samples of speed_scale [-]; +inf at rest throughout.
  double safe_speed_scale = 0.0;
  std::optional<std::size_t> worst_sample;  ///< the sample that sets it
  std::size_t unsafe_sample_count = 0;
  /// One sentence: "unsafe: slow the trajectory to 0.73× (worst at t = 0.42 s: chest (sternum), force)".
  std::string message;
};

/// Judges every sample of a motion against `regions` with `scene`'s robot radius, covering,
/// contact type and contact area (its mass and speed are each sample's).
/// @throws std::invalid_argument for an empty `regions`, a bad sample (as CheckTrajectory) or as
///         JudgeBodyContact for the scene (e.g. a fixed robot with a clamped contact).
BodyRegionTrajectoryCheck CheckTrajectoryForBodyRegions(const BodyContactScene& scene,
                                                        std::span<const materials::BodyLimits> regions,
                                                        std::span<const MotionSample> samples,
                                                        const BodyRegionOptions& options = {});

}  // namespace covopt::optim
