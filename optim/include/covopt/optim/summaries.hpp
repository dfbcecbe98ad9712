#pragma once
/// @file summaries.hpp
/// The result summary (covopt/core/result_summary.hpp) of optim's results, built here beside
/// them: every front end prints what these return, and none judges again.

#include <optional>
#include <span>
#include <string_view>

#include <covopt/core/result_summary.hpp>
#include <covopt/core/scene.hpp>

#include "covopt/optim/body_region_check.hpp"
#include "covopt/optim/body_region_trajectory.hpp"
#include "covopt/optim/design.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "covopt/optim/speed_limit_table.hpp"
#include "covopt/optim/trajectory_check.hpp"

namespace covopt::optim {

/// `optimize`: the recommended design's head verdict; without a recommendation the bare robot's
/// rows (safe only when the bare robot is, kBareRobotSafe). The covering is the recommendation's.
ResultSummary SummarizeDesign(const DesignRequest& request, const DesignResult& result);

/// `speed-limit`: one LimitRow per row (the max safe speed per reflected mass, or the max safe
/// mass per speed) with the criterion that binds it, the covering's law and validity there; 0
/// when no value is safe, +inf when safe up to the search limit. The robot is the scene's
/// (without the quantity solved for); the covering the scene's, named by the rows' material.
ResultSummary SummarizeSpeedLimits(SpeedLimitQuantity quantity, const Scene& scene, const SpeedLimitOptions& options,
                                   std::span<const SpeedLimitRow> rows);

/// `robot --trajectory`: the verdict rows of the sample that sets the safe speed scale (the
/// worst), its time, speed and reflected mass as the governing case; not evaluated when a
/// sample failed; no rows (SAFE) when the point is at rest throughout. The robot's model file
/// and joints are the caller's (optim does not read robots): it sets summary.robot.
ResultSummary SummarizeTrajectory(const TrajectoryCheck& check, const Scene& scene, std::string_view material);

/// A body region as a target: "chest (sternum)".
std::string RegionTarget(const materials::BodyLimits& limits);

/// The table `limits` come from (title, edition, source, SHA-256); none without a region.
std::optional<LimitTableSummary> LimitTableOf(const materials::BodyLimits& limits);

/// Adds the table `limits` come from (title, edition, source, SHA-256) to the summary's
/// limit_tables, once, and its edition to the standards, once.
void AddLimitTable(ResultSummary& summary, const materials::BodyLimits& limits);

/// `simulate --body-region`: each region's verdict row by row ("chest (sternum)"), then the
/// head's rows when it is judged too (`head`, the head's own summary: SummarizeImpact).
ResultSummary SummarizeBodyContact(const BodyContactScene& scene, std::string_view material,
                                   std::span<const BodyRegionJudgement> regions, const ResultSummary* head);

/// `optimize --body-region`: the recommended covering's verdicts on every region (and the head's
/// when judged); without a recommendation the bare robot's, safe only when it is.
ResultSummary SummarizeBodyRegionDesign(const BodyRegionDesignRequest& request, const BodyRegionDesignResult& result);

/// `robot --trajectory --body-region`: one row, the worst sample's worst region (its ratio, the
/// limit that binds); `head` the head's own check's summary when judged (its rows join).
ResultSummary SummarizeBodyRegionTrajectory(const BodyRegionTrajectoryCheck& check,
                                            std::span<const materials::BodyLimits> regions,
                                            const BodyContactScene& scene, double safety_factor);

/// Appends the rows, targets, criteria, standards and scope of `more` to `summary` (call
/// Finish after): one summary of several targets judged apart (the head beside the regions).
void AppendSummary(ResultSummary& summary, const ResultSummary& more);

}  // namespace covopt::optim
