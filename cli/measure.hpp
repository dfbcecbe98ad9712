#pragma once
/// @file measure.hpp
/// `covopt measure`: what a biofidelic force-measuring device (a spring and a Shore A pad,
/// fixed) would read when the robot strikes it, beside the body model's prediction for the same
/// robot, speed, covering and ISO/TS 15066 region (optim/measurement.hpp, docs/guide/limits.md).
///
///     covopt measure --body-region chest --robot-mass 10kg --speed 0.25m/s --robot-radius 50mm
///                    [--device 25+70 | --device chest | --device-spring 25N/mm --device-pad 70ShA,7mm]
///
/// Exit codes: 0 done, 1 an output failed, 2 bad input (one message on stderr naming the flag).

#include <optional>
#include <ostream>
#include <string>

#include "run_context.hpp"
#include "simulation_plan.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The options of `covopt measure`, as typed.
struct MeasureOptions {
  /// The robot, its covering and the region: simulate's scene and --body-region flags.
  SimulateOptions scene;
  /// --device PAIR|REGION: a spring and pad pair ("25+70") or the region it stands for.
  std::optional<std::string> device;
  /// --device-spring STIFFNESS (e.g. 25N/mm) and --device-pad HARDNESS[,THICKNESS] (70ShA,7mm).
  std::optional<std::string> device_spring;
  std::optional<std::string> device_pad;
  /// --device-pad-thickness LENGTH: the pad's thickness with --device (default 7 mm, assumed).
  std::optional<std::string> device_pad_thickness;
  /// Not typed: the run's command line and files (RunCli).
  std::optional<RunContext> run;
};

/// Registers the options of `measure` into `options`, which must outlive the parse.
void SetupMeasure(CLI::App* sub, MeasureOptions& options);

/// Runs the subcommand; returns the exit code (0, 1 or 2).
int RunMeasure(const MeasureOptions& options, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
