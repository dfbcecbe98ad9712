#include "covopt/optim/target_speed_limits.hpp"

#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

namespace covopt::optim {
namespace {

/// "…: <message>" of the first limit the evaluation failed on, if any.
template <typename Limit>
std::string Failure(std::initializer_list<const Limit*> limits, const char* what) {
  for (const Limit* limit : limits) {
    if (limit && limit->status == SpeedLimitStatus::kEvaluationFailed) {
      return std::string(what) + " could not be evaluated: " + limit->message;
    }
  }
  return {};
}

}  // namespace

TargetSpeedLimits TargetSpeedLimitTable(const TargetSpeedLimitRequest& request,
                                        const materials::ContactTargets& targets) {
  TargetSpeedLimits out;
  const std::vector<materials::BodyLimits> iso = targets.IsoLimits();
  for (const double mass : request.robot_masses_kg) {
    BodyContactScene scene = request.contact_scene;
    scene.robot_mass_kg = mass;
    const std::vector<BodyRegionSpeedLimitRow> table =
        iso.empty() ? std::vector<BodyRegionSpeedLimitRow>{}
                    : BodyRegionSpeedLimitTable(scene, iso, request.region_options, request.time_path);
    for (const BodyRegionSpeedLimitRow& row : table) {
      out.failure = Failure<BodyRegionSpeedLimit>({&row.bare, row.covered ? &*row.covered : nullptr}, "the speed limit");
      if (!out.failure.empty()) return out;
    }
    std::size_t next = 0;  // the rows in the targets' order (the head where it was named)
    for (const materials::ContactTarget& target : targets.targets) {
      TargetSpeedLimit& row = out.rows.emplace_back();
      row.robot_mass_kg = mass;
      if (!target.is_head()) {
        row.region = table.at(next++);
        continue;
      }
      SpeedLimitOptions options = request.head_options;
      Scene head = request.scene;
      head.robot.mass_kg = mass;
      if (head.covering.thickness_m > 0.0) row.head_covered = MaxSafeSpeed(head, options);
      head.covering.thickness_m = 0.0;
      options.covering_compressive_strength_Pa = 0.0;
      row.head_bare = MaxSafeSpeed(head, options);
      out.failure = Failure<SpeedLimit>({&*row.head_bare, row.head_covered ? &*row.head_covered : nullptr},
                                        "the head's speed limit");
      if (!out.failure.empty()) return out;
    }
  }
  return out;
}

}  // namespace covopt::optim
