#pragma once
/// @file workprecision.hpp
/// `covopt workprecision`: speed against accuracy of every time-integration method.
///
/// The study itself is the library's covopt::MeasureWorkPrecision
/// (covopt/core/work_precision.hpp): each SUNDIALS method, with and without the restart at
/// the force law's phase switches, over a ladder of relative tolerances, measured against
/// the exact path and timed (median CPU time per impact); with --design, the optimiser-level
/// study (covopt/optim/design_work_precision.hpp). This file parses the flags into
/// its options and prints the result: a table, --json, --csv, and two gnuplot charts
/// (worst error against time per impact; worst error against the requested tolerance). Exit codes: 0 done (failed runs are data, reported with their status),
/// 1 an output could not be written, 2 bad input.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "covopt/core/work_precision.hpp"
#include "simulate.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The options of `covopt workprecision`, as typed (covopt::WorkPrecisionOptions is the
/// library's, which these become).
struct WorkPrecisionOptions {
  /// The scene flags and --scene/--material of `covopt simulate` (its computation and
  /// output options are not used).
  SimulateOptions scene;
  /// --methods a,b,...: integrators by name (TimeIntegrationMethods()); default all.
  std::vector<std::string> methods;
  /// --tolerances: "1e-3..1e-12" (every decade between, either order) or a list "1e-4,1e-8".
  std::string tolerances = "1e-3..1e-12";
  /// --restart on|off|both: restart at the phase switches (on), integrate straight
  /// through the kinks (off), or both as separate series.
  std::string restart = "both";
  /// --repeats N: timed runs per point (the median is reported); 0 = automatic (at least
  /// 3, more for fast runs, about 2 ms of runs per point).
  int repeats = 0;
  bool json = false;
  std::optional<std::string> csv_file;
  /// --plot FILE: worst error against CPU time per impact (log-log), one line per series.
  std::optional<std::string> plot_file;
  /// --tolerance-plot FILE: worst error against requested relative tolerance.
  std::optional<std::string> tolerance_plot_file;
  /// --title TEXT: a name for the scene in chart titles (default: the scene headline).
  std::optional<std::string> title;
  /// --design: the optimiser-level study instead (covopt::optim::MeasureDesignWorkPrecision):
  /// the thinnest-safe-covering search on the exact path and on the time path per
  /// (integrator, rtol), the errors of b_c* and E_c* against the exact path's optimum and
  /// the search's CPU time. Default methods arkode-erk54, cvode-adams, cvode-bdf; default
  /// tolerances 1e-4..1e-10.
  bool design = false;
  /// Not typed: the command line and input files for the JSON's provenance, set by RunCli.
  std::optional<RunContext> run;
};

/// Reads "1e-3..1e-12" (decades between, inclusive) or "1e-4,1e-6,1e-8" into tolerances
/// in [1e-14, 1e-2]. @throws InputError naming --tolerances.
std::vector<double> ParseToleranceLadder(const std::string& text);

/// The CSV of `covopt workprecision --csv`: a header, then one row per point.
std::string WorkPrecisionCsv(const std::vector<covopt::WorkPrecisionPoint>& points);

/// Registers the options of the `workprecision` subcommand `sub` (made by RunCli with its name
/// and summary).
void SetupWorkPrecision(CLI::App* sub, WorkPrecisionOptions& options);

/// Runs the subcommand; returns the exit code (0, 1 or 2).
int RunWorkPrecision(const WorkPrecisionOptions& options, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
