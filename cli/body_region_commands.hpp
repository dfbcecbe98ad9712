#pragma once
/// @file body_region_commands.hpp
/// The --body-region forms of `simulate`, `speed-limit` and `optimize` (docs/model.md §13): each
/// reads its command's options as the command does, then makes the library's body-region calls
/// (optim::JudgeBodyContact, optim::BodyRegionSpeedLimitTable, optim::DesignForBodyRegions) and
/// prints a table or JSON (report/body_contact_json.hpp). The head, when named, keeps its model
/// and Park et al.'s criteria.

#include <ostream>
#include <string>
#include <vector>

#include "body_region_options.hpp"
#include "covopt/optim/design.hpp"
#include "optimize.hpp"
#include "simulate.hpp"
#include "speed_limit.hpp"
#include "sweep.hpp"

namespace covopt::cli {

/// `simulate --body-region ...`: per target the body contact's peaks and verdicts (the head:
/// simulate's own table). Returns the exit code.
int RunBodyRegionSimulate(const SimulateOptions& options, const BodyRegionPlan& regions, std::ostream& out,
                          std::ostream& err);

/// `speed-limit --body-region ...`: one row per target, bare and with the covering, one block
/// per covering (--material) and robot mass. Returns the exit code.
int RunBodyRegionSpeedLimit(const SpeedLimitCommandOptions& options, const BodyRegionPlan& regions,
                            std::ostream& out, std::ostream& err);

/// `optimize --body-region ... --speed V`: the covering that lets the robot reach V for every
/// target. `head` is optimize's resolved request (the robot, the head, the candidates, the
/// rule's flags), `warnings` its input warnings. Returns the exit code.
int RunBodyRegionOptimize(const OptimizeOptions& options, const optim::DesignRequest& head,
                          const std::vector<std::string>& warnings, const BodyRegionPlan& regions, std::ostream& out,
                          std::ostream& err);

/// `sweep --body-region R` (one ISO region): the body contact's ratios per grid point, as CSV
/// columns (or a summary), computed point by point on the exact path; no chart.
int RunBodyRegionSweep(const SweepCommandOptions& options, const BodyRegionPlan& regions, std::ostream& out,
                       std::ostream& err);

}  // namespace covopt::cli
