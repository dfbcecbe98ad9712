#pragma once
/// @file robot.hpp
/// `covopt robot`: the reflected mass of a robot (URDF) at a contact point, in a
/// configuration, along an impact direction, and its extremes over all directions.
///
///     covopt robot --urdf FILE [--base LINK] --tip LINK --joints Q1,Q2,... [--point X,Y,Z]
///                  [--direction X,Y,Z] [--json]
///     covopt robot --urdf FILE [--base LINK] --tip LINK [--point X,Y,Z] --trajectory FILE.csv
///                  [scene flags, limits] [--json] [--csv FILE|-] [--plot FILE.png|FILE.svg]
///
/// Without --direction only the extremes are printed (JSON: reflected_mass_kg and direction
/// null). Exit codes: 0 done (also when some direction is fixed: a warning), 2 bad input.

#include <ostream>

#include "robot_model_options.hpp"
#include "robot_trajectory.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The options of `covopt robot`, as typed.
struct RobotOptions {
  RobotModelOptions model;  ///< --urdf/--base/--tip/--joints/--point/--direction
  bool json = false;        ///< --json: print report::RobotJson
  /// --trajectory FILE.csv and the check's flags: the trajectory safety check instead.
  RobotTrajectoryOptions trajectory;
  /// Not typed: the command line and input files for the JSON's provenance, set by RunCli.
  std::optional<RunContext> run;
};

/// Registers the options of the `robot` subcommand `sub` (made by RunCli with its name and
/// summary); `options` must outlive the parse.
void SetupRobot(CLI::App* sub, RobotOptions& options);

/// Runs the subcommand: one call to robot::ReflectedMass, or with --trajectory the check of
/// robot_trajectory.hpp; returns the exit code (0 or 2; 1 when a check's output fails).
int RunRobot(const RobotOptions& options, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
