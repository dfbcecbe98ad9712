#pragma once
/// @file target_speed_limits.hpp
/// The all-targets speed-limit table of `covopt speed-limit --body-region` and
/// `covopt.speed_limit(body_region=...)`, computed once for both shells: per robot mass, one
/// row per target in the order named, an ISO region's by BodyRegionSpeedLimitTable, the head's
/// by MaxSafeSpeed (bare, and with the covering). report::TableRow lays a row out.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include <covopt/core/scene.hpp>
#include <covopt/materials/contact_target.hpp>

#include "covopt/optim/body_region_check.hpp"
#include "covopt/optim/speed_limit.hpp"

namespace covopt::optim {

/// One target's speed limits at one robot mass: an ISO region's row, or the head's pair.
struct TargetSpeedLimit {
  double robot_mass_kg = 0.0;                      ///< [kg]; +inf: fixed
  std::optional<BodyRegionSpeedLimitRow> region;   ///< an ISO target's
  std::optional<SpeedLimit> head_bare;             ///< the head's, bare robot
  std::optional<SpeedLimit> head_covered;          ///< the head's with the covering; empty without one
};

/// What the table is computed for.
struct TargetSpeedLimitRequest {
  Scene scene;  ///< the head's scene (robot, covering and the head's model)
  /// The ISO regions' contact (scene_file::BodyContactSceneOf: the scene's robot and covering
  /// with the targets' contact and contact area); its mass is each row's.
  BodyContactScene contact_scene;
  std::vector<double> robot_masses_kg;
  BodyRegionOptions region_options;  ///< the ISO regions' rule and material
  SpeedLimitOptions head_options;    ///< the head's (its covering's compressive strength set)
  TimeIntegrationOptions time_path;  ///< a braking robot's time path
};

/// The rows, mass by mass, or the first failure.
struct TargetSpeedLimits {
  std::vector<TargetSpeedLimit> rows;
  /// "the speed limit could not be evaluated: ..." (or "the head's ..."): a limit the time
  /// path could not answer, which is no answer at all; empty when every limit was evaluated.
  std::string failure;
};

/// The table for `targets`.
/// @throws std::invalid_argument as BodyRegionSpeedLimitTable and MaxSafeSpeed.
TargetSpeedLimits TargetSpeedLimitTable(const TargetSpeedLimitRequest& request,
                                        const materials::ContactTargets& targets);

}  // namespace covopt::optim
