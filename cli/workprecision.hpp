#pragma once
/// @file workprecision.hpp
/// `covopt workprecision`: speed against accuracy of every time-integration method.
///
/// For one scene, each SUNDIALS method (CVODE Adams/BDF, ARKODE explicit and diagonally
/// implicit RK), with and without the restart at the force law's phase switches, runs over
/// a ladder of relative tolerances. Each run is compared with the exact path, which is the
/// reference for every peak (error 0 by definition), and timed: the CPU time per impact is
/// the median of repeated runs on this thread. Output: a table, --json, --csv, and two
/// gnuplot charts (worst error against time per impact; worst error against the requested
/// tolerance). Exit codes: 0 done (failed runs are data, reported with their status),
/// 1 an output could not be written, 2 bad input.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"
#include "simulate.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The options of `covopt workprecision`, as typed.
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
};

/// One run of one method at one tolerance, measured against the exact path.
struct WorkPrecisionPoint {
  ComputationMethod method = ComputationMethod::kExact;
  bool restart = true;                 ///< restarted at the phase switches
  double relative_tolerance = 0.0;     ///< requested rtol [-] (atol = rtol); 0 for exact
  SolveStatus status = SolveStatus::kSuccess;
  std::string message;                 ///< the integrator's message on failure
  /// Relative errors against the exact path [-] (0 for the exact path itself).
  double error_max_penetration = 0.0;
  double error_peak_force = 0.0;
  double error_max_compressive_stress = 0.0;
  double error_max_energy_density = 0.0;
  double error_contact_duration = 0.0;
  double worst_error = 0.0;            ///< the largest of the five
  std::optional<double> energy_residual;  ///< the time path's self-check [-]
  double seconds_per_impact = 0.0;     ///< median CPU time of one computation [s]
  int timed_runs = 0;
  SolverStatistics statistics;         ///< of one run
  std::size_t warning_count = 0;       ///< warnings the result carried
};

/// What to measure.
struct WorkPrecisionPlan {
  std::vector<ComputationMethod> methods;
  std::vector<double> tolerances;
  std::vector<bool> restarts;  ///< series: with restart (true), without (false), or both
  int repeats = 0;             ///< 0 = automatic
};

/// Measures the exact path (first point) and every (method, restart, tolerance).
std::vector<WorkPrecisionPoint> MeasureWorkPrecision(const ImpactModel& model,
                                                     const WorkPrecisionPlan& plan);

/// Reads "1e-3..1e-12" (decades between, inclusive) or "1e-4,1e-6,1e-8" into tolerances
/// in [1e-14, 1e-2]. @throws InputError naming --tolerances.
std::vector<double> ParseToleranceLadder(const std::string& text);

/// The CSV of `covopt workprecision --csv`: a header, then one row per point.
std::string WorkPrecisionCsv(const std::vector<WorkPrecisionPoint>& points);

/// Adds the `workprecision` subcommand to `app`.
CLI::App* SetupWorkPrecision(CLI::App& app, WorkPrecisionOptions& options);

/// Runs the subcommand; returns the exit code (0, 1 or 2).
int RunWorkPrecision(const WorkPrecisionOptions& options, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
