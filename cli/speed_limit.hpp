#pragma once
/// @file speed_limit.hpp
/// `covopt speed-limit`: the largest safe impact speed of a robot with its covering (the speed
/// a power-and-force-limiting controller enforces), or with --solve-for mass the largest safe
/// reflected mass at a speed.
///
///     covopt speed-limit [scene flags] [--material NAME]... [--robot-mass 0.5kg..50kg:log:20,fixed]
///                        [--solve-for speed|mass] [--safety-factor X] [--allow-full-compression]
///                        [--oracle auto|exact|time-path] [--method INTEGRATOR] [--rtol X]
///                        [--json] [--csv FILE|-] [--plot FILE.png|FILE.svg]
///
/// The scene comes from Scene{}, --scene, the scene flags and --material exactly as in
/// `covopt simulate` (ResolveSimulation); --robot-mass (or --speed with --solve-for mass) may
/// be a list or range in the sweep syntax (ParseSweepAxis), one row per value; several
/// --material give one block of rows (and one chart curve) each. Each row is one library call,
/// optim::MaxSafeSpeed or optim::MaxSafeMass; the JSON is report::SpeedLimitJson.
/// Exit codes: 0 an answer (also "no speed is safe"), 1 an output could not be written,
/// 2 bad input.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "covopt/optim/speed_limit.hpp"
#include "covopt/optim/speed_limit_table.hpp"
#include "covopt/report/speed_limit_json.hpp"
#include "oracle_options.hpp"
#include "plot.hpp"
#include "body_region_options.hpp"
#include "limit_search_output.hpp"
#include "simulation_plan.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The options of `covopt speed-limit`, as typed.
struct SpeedLimitCommandOptions {
  /// The scene flags, --scene, --thresholds, --catalog/--no-builtin, the limits and
  /// --safety-factor, read as `covopt simulate` reads them. Its robot.mass (robot.speed with
  /// --solve-for mass) may be a list or range; its `material` stays unset (see materials).
  SimulateOptions scene;
  /// --material NAME (repeatable): one block of rows and one chart curve per material.
  std::vector<std::string> materials;
  /// --solve-for speed (default) | mass.
  std::optional<std::string> solve_for;
  /// --allow-full-compression: the paper's criterion (the ratios only).
  bool allow_full_compression = false;
  /// --allow-crushing: a sacrificial liner; its crush ratio does not limit.
  bool allow_crushing = false;
  /// --oracle, --method, --rtol: which path judges the impacts (as `covopt optimize`).
  OracleFlags oracle;
  bool json = false;                      ///< --json
  std::optional<std::string> csv_file;    ///< --csv FILE ("-": stdout instead of the table)
  std::optional<std::string> plot_file;   ///< --plot FILE.png|FILE.svg (solve-for speed)
  ReportFlags report;  ///< --report FILE.html|FILE.pdf and the sign-off flags (report_option.hpp)
  /// Not typed: the command line and input files for the JSON's provenance, set by RunCli.
  std::optional<RunContext> run;
};

/// What the options resolve to.
struct SpeedLimitPlan {
  optim::SpeedLimitQuantity quantity = optim::SpeedLimitQuantity::kSpeed;
  /// One resolved scene per covering (per --material, or the scene's own covering).
  std::vector<SimulationPlan> coverings;
  /// The values the rows vary: reflected masses [kg] (solving for the speed; +inf = fixed)
  /// or speeds [m/s] (solving for the mass). One value: the scene's own.
  std::vector<double> values;
  /// How messages name where the values came from: "--robot-mass '0.5kg..50kg'" or "".
  std::string values_source;
  optim::SpeedLimitOptions options;
  /// About the oracle flags (e.g. --rtol not used because auto chose the exact path).
  std::vector<std::string> warnings;
  bool json = false;
  std::optional<std::string> csv_file;
  std::optional<std::string> plot_file;
  PlotFormat plot_format = PlotFormat::kPng;
};

/// Registers the options of the `speed-limit` subcommand `sub` (made by RunCli with its name
/// and summary), storing what is typed into `options`.
void SetupSpeedLimit(CLI::App* sub, SpeedLimitCommandOptions& options);

/// Reads and checks the options (the scene's ranges are left to the library).
/// @throws InputError naming the flag, the value and what is allowed.
SpeedLimitPlan ResolveSpeedLimit(const SpeedLimitCommandOptions& options);

/// The Safety-Map chart of the plan (report::SpeedLimitChart; computes its curves).
report::GnuplotChart SpeedLimitChartOf(const SpeedLimitPlan& plan);

/// `speed-limit --body-region ...` (speed_limit_body_region.cpp): one row per target, bare and
/// with the covering, one block per covering (--material) and robot mass. Returns the exit code.
int RunBodyRegionSpeedLimit(const SpeedLimitCommandOptions& options, const BodyRegionPlan& regions,
                            std::ostream& out, std::ostream& err);

/// Runs the subcommand; returns the exit code (0, 1 or 2).
int RunSpeedLimit(const SpeedLimitCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
