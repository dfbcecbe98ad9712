#pragma once
/// @file simulate.hpp
/// `covopt simulate`: one impact, its peaks and the injury verdicts.
///
/// The scene is Scene{} (the paper's), then the --scene file, then the flags
/// (simulation_plan.hpp). The exact path answers unless a history or a plot is asked for, or
/// the scene has a braking robot or a neck (docs/model.md §10), which need the time path.
/// Exit codes: 0 done, 1 the computation or an output failed, 2 bad input (one message on
/// stderr, nothing on stdout).

#include <ostream>

#include "body_region_options.hpp"
#include "simulation_plan.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// Registers the options of the `simulate` subcommand `sub` (made by RunCli with its name and
/// summary), storing what is typed into `options`, which must outlive the parse.
void SetupSimulate(CLI::App* sub, SimulateOptions& options);

/// Runs the subcommand; returns the exit code (0, 1 or 2).
int RunSimulate(const SimulateOptions& options, std::ostream& out, std::ostream& err);

/// `simulate --body-region ...` (simulate_body_region.cpp): per target the body contact's
/// peaks and verdicts (the head: simulate's own table). Returns the exit code.
int RunBodyRegionSimulate(const SimulateOptions& options, const BodyRegionPlan& regions, std::ostream& out,
                          std::ostream& err);

}  // namespace covopt::cli
