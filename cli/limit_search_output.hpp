#pragma once
/// @file limit_search_output.hpp
/// The lines a limit search prints (`speed-limit`, `robot --trajectory`): its limits, the
/// criterion and the scope of the head's verdicts. Shared by those commands' files.

#include <ostream>

#include "covopt/optim/speed_limit.hpp"
#include "simulation_plan.hpp"

namespace covopt::cli {

/// The Limits and Criterion lines of a limit search on `covering` (its crush check).
void PrintLimitsAndCriterion(std::ostream& out, const optim::SpeedLimitOptions& options,
                             const SimulationPlan& covering);
/// The rule a limit search on `covering` applies (crushing checked where its strength is known).
optim::DesignRule LimitRule(const optim::SpeedLimitOptions& options, const SimulationPlan& covering);
/// The Scope block: what the verdicts cover (optim::HeadVerdictScope).
void PrintHeadScope(std::ostream& out, const optim::SpeedLimitOptions& options, const SimulationPlan& covering);

}  // namespace covopt::cli
