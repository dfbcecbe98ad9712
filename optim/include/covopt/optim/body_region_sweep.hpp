#pragma once
/// @file body_region_sweep.hpp
/// One ISO/TS 15066 body region's verdict over a grid of the robot's and the covering's
/// quantities (docs/model.md §13): what `covopt sweep --body-region` and covopt.sweep(...,
/// body_region=...) compute. Each point is JudgeBodyContact on the exact path; a point
/// outside the model's range carries the library's message instead of a verdict.

#include <optional>
#include <string>
#include <vector>

#include <covopt/core/body_contact.hpp>
#include <covopt/core/sweep.hpp>
#include <covopt/materials/body_regions.hpp>

#include "covopt/optim/body_region_check.hpp"

namespace covopt::optim {

/// One grid point of SweepBodyRegion.
struct BodyRegionSweepPoint {
  double x = 0.0;  ///< the x axis' value [SI: kg, m/s, m or Pa, - for a Poisson ratio]
  double y = 0.0;  ///< the y axis' value [SI]; 0 without a y axis
  /// The verdict at the point; empty when the point is outside the model's range.
  std::optional<BodyRegionJudgement> judgement;
  /// Why the point has no verdict (JudgeBodyContact's message); "" when it has one.
  std::string error;
};

/// The scene fields a body contact reads, and so may be swept: robot.mass, robot.speed,
/// robot.radius and covering.* (their SceneField dotted names).
bool IsBodyContactField(std::string_view dotted_name) noexcept;

/// Judges `limits` at every point of the grid `x` (× `y`): `scene` with the axes' fields set
/// (SceneFields() names: "robot-mass", "speed", "robot-radius", "covering-modulus",
/// "covering-poisson", "covering-thickness", or their dotted names). The points are in
/// core's Sweep order: index ix × ny + iy (x varies slowest).
/// @throws std::invalid_argument for an unknown quantity, one the body contact does not read,
///         an axis without values, or a grid over covopt::kMaxSweepAxisValues values per axis or
///         covopt::kMaxSweepPoints points (CheckSweepSize, before any point; a point's own bad
///         value is that point's error).
std::vector<BodyRegionSweepPoint> SweepBodyRegion(const BodyContactScene& scene, const SweepAxis& x,
                                                  const std::optional<SweepAxis>& y,
                                                  const materials::BodyLimits& limits,
                                                  const BodyRegionOptions& options = {});

}  // namespace covopt::optim
