#pragma once
/// @file robot_trajectory.hpp
/// `covopt robot --trajectory FILE.csv`: is a robot motion safe with this covering, and by
/// how much may it be sped up or must it be slowed down?
///
///     covopt robot --urdf FILE [--base LINK] --tip LINK [--point X,Y,Z] --trajectory FILE.csv
///                  [scene flags] [--scene FILE.toml] [--material NAME] [limits]
///                  [--safety-factor X] [--allow-full-compression]
///                  [--json] [--csv FILE|-] [--plot FILE.png|FILE.svg]
///
/// The pipeline: robot::ReadJointTrajectory -> robot::ContactMotion (per sample the contact
/// point's speed |J_v q̇| and the reflected mass along its motion) -> optim::MotionSamples ->
/// optim::CheckTrajectory, the one library call that judges the motion. The covering, head
/// and limits come from the scene flags as in `covopt speed-limit` (ResolveSimulation); the
/// robot's mass and speed come from each sample, so --robot-mass, --speed, --joints and
/// --direction are bad input here. The JSON is report::TrajectoryCheckJson.
/// Exit codes: 0 an answer (safe, unsafe or at rest), 1 an output could not be written,
/// 2 bad input.

#include <optional>
#include <ostream>
#include <string>

#include "robot_model_options.hpp"
#include "run_context.hpp"
#include "simulation_plan.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The options of the trajectory check, as typed.
struct RobotTrajectoryOptions {
  std::optional<std::string> file;  ///< --trajectory FILE.csv
  /// The scene flags, --scene, --material, --catalog/--no-builtin, the limits and
  /// --safety-factor, read as `covopt speed-limit` reads them (its robot_model stays unset:
  /// the robot is RobotOptions::model).
  SimulateOptions scene;
  /// --allow-full-compression: the paper's criterion (the ratios only).
  bool allow_full_compression = false;
  std::optional<std::string> csv_file;   ///< --csv FILE ("-": stdout instead of the table)
  std::optional<std::string> plot_file;  ///< --plot FILE.png|FILE.svg
  ReportFlags report;  ///< --report FILE.html|FILE.pdf and the sign-off flags (report_option.hpp)
  /// The first flag of the check typed ("--covering-thickness", "--csv", ...), if any: they
  /// apply with --trajectory only.
  std::optional<std::string> FirstCheckFlag() const;
};

/// Adds --trajectory and the check's flags (scene, limits, outputs) to the `robot`
/// subcommand `sub`; `options` must outlive the parse.
void AddRobotTrajectoryOptions(CLI::App& sub, RobotTrajectoryOptions& options);

/// Runs the check (`options.file` set): the robot from `model` (--urdf, --base, --tip,
/// --point; --joints and --direction are bad input), --json printing
/// report::TrajectoryCheckJson with the provenance of `context`. Returns the exit code (0, 1 or 2).
int RunRobotTrajectory(const RobotModelOptions& model, const RobotTrajectoryOptions& options, bool json,
                       const std::optional<RunContext>& context, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
