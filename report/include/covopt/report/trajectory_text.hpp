#pragma once
/// @file trajectory_text.hpp
/// The readable tables of a trajectory check (`covopt robot --trajectory`'s text;
/// trajectory_json.hpp is its JSON and CSV).

#include <ostream>
#include <vector>

#include <covopt/materials/body_regions.hpp>
#include <covopt/optim/body_region_trajectory.hpp>
#include <covopt/optim/trajectory_check.hpp>

namespace covopt::report {

/// The samples' table: all of a short trajectory (up to 20 samples); else the 10 moving
/// samples with the smallest speed scale and every unsafe one, at most 30, in time order.
void PrintTrajectorySamples(std::ostream& out, const optim::TrajectoryCheck& check);

/// The "Worst" line: the sample that sets the speed scale, its speed, reflected mass and max
/// safe speed; nothing when there is none.
void PrintWorstSample(std::ostream& out, const optim::TrajectoryCheck& check);

/// The body-region check's table: all of a short trajectory (up to 20 samples), else the 10
/// moving samples with the smallest speed scale, in time order; each with its worst ratio,
/// what binds and where (`iso`, the regions' limits the check was run against).
void PrintBodyRegionSamples(std::ostream& out, const optim::BodyRegionTrajectoryCheck& check,
                            const std::vector<materials::BodyLimits>& iso);

}  // namespace covopt::report
