#pragma once
/// @file work_precision.hpp
/// The work-precision study: speed against accuracy of every time-integration method.
///
/// For one scene, each requested SUNDIALS method (CVODE Adams/BDF, ARKODE explicit and
/// diagonally implicit RK), with and without the restart at the force law's phase switches,
/// runs over a list of relative tolerances. Each run is compared with the exact path, the
/// reference for every peak (docs/model.md §3), and timed: the CPU time per impact is the
/// median of repeated runs on the calling thread (CLOCK_THREAD_CPUTIME_ID), so other load on
/// the machine hardly moves it.
///
/// A failed integration is data (a point with its status), not an error; only a failed exact
/// path leaves the study without a reference. The library never prints: progress is reported
/// through WorkPrecisionOptions::progress. `covopt workprecision` is this call plus a table,
/// JSON, CSV and charts.
///
///     covopt::WorkPrecisionOptions options;
///     options.methods = {covopt::ComputationMethod::kArkodeErk54};
///     options.relative_tolerances = {1e-4, 1e-6, 1e-8};
///     const covopt::WorkPrecisionResult study = covopt::MeasureWorkPrecision(scene, options);
///     std::cout << study.BriefReport() << '\n';

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/scene.hpp"

namespace covopt {

/// Which series to measure per method: with the restart at the phase switches, integrating
/// straight through the C⁰ kinks, or both (with restart first).
enum class RestartSeries {
  kOn,    ///< restart at every phase switch (the correct way)
  kOff,   ///< straight through the kinks with the full piecewise law
  kBoth,  ///< both, as two series per method
};
std::string_view ToString(RestartSeries series) noexcept;

/// Progress of a running study.
struct WorkPrecisionProgress {
  std::size_t completed_runs = 0;  ///< points measured so far (the exact path is the first)
  std::size_t total_runs = 0;      ///< 1 + methods x restart series x tolerances
};

/// What to measure and how long to time it.
struct WorkPrecisionOptions {
  /// Integrators to measure, in this order: any ComputationMethod but kExact, each at most
  /// once, at least one. Default: every time-integration method (TimeIntegrationMethods()).
  std::vector<ComputationMethod> methods = TimeIntegrationMethods();
  /// Requested relative tolerances rtol [-] (atol = rtol), in the order measured, each in
  /// [1e-14, 1e-2], at least one. Default: every decade from 1e-3 to 1e-12.
  std::vector<double> relative_tolerances = {1e-3, 1e-4, 1e-5, 1e-6,  1e-7,
                                             1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
  /// Restart series per method. Default: both.
  RestartSeries restart = RestartSeries::kBoth;
  /// Timed runs per point, the median reported, in [0, 100000]; 0 = automatic: enough runs
  /// to fill timing_budget_s judged by the first run's time, at least 3 and at most 301.
  /// Default: 0 (automatic).
  int repetitions = 0;
  /// With repetitions = 0: the CPU time to spend timing each point [s], in (0, 60].
  /// Default: 2e-3 s.
  double timing_budget_s = 2e-3;
  /// Step limit of each integration (TimeIntegrationOptions::max_steps), >= 10; a run
  /// hitting it is a failed point (SolveStatus::kStepLimit). Default: 200000.
  long max_steps_per_run = 200000;
  /// Worst errors [-] for which the result names the cheapest run reaching them, each > 0.
  /// Default: 1e-3, 1e-6, 1e-9.
  std::vector<double> error_targets = {1e-3, 1e-6, 1e-9};
  /// A series "keeps its tolerance" when its worst error stays within this many times the
  /// requested rtol at every tolerance [-], > 0. The global error of a well-behaved
  /// integrator stays within a few tens of its local tolerance on these scenes.
  /// Default: 100.
  double kept_tolerance_ratio = 100.0;
  /// Called after each measured point (the exact path first), on the calling thread.
  /// Default: none.
  std::function<void(const WorkPrecisionProgress&)> progress;
};

/// One run of one method at one tolerance, measured against the exact path. The exact path
/// itself is a point too (method kExact, errors 0).
struct WorkPrecisionPoint {
  ComputationMethod method = ComputationMethod::kExact;
  bool restart = true;              ///< restarted at the phase switches
  double relative_tolerance = 0.0;  ///< requested rtol [-] (atol = rtol); 0 for the exact path
  SolveStatus status = SolveStatus::kSuccess;
  std::string message;              ///< the integrator's message on failure
  /// Relative errors |x / x_exact - 1| against the exact path [-] (0 for the exact path;
  /// NaN for a failed run).
  double error_max_penetration = 0.0;
  double error_peak_force = 0.0;
  double error_max_compressive_stress = 0.0;
  double error_max_energy_density = 0.0;
  double error_contact_duration = 0.0;
  double worst_error = 0.0;             ///< the largest of the five [-] (NaN for a failed run)
  std::optional<double> energy_residual;  ///< the time path's energy self-check [-]
  double seconds_per_impact = 0.0;      ///< median CPU time of one computation [s]
  int timed_runs = 0;                   ///< runs behind the median
  SolverStatistics statistics;          ///< counters of one run
  std::size_t warning_count = 0;        ///< validity warnings the result carried

  bool ok() const noexcept { return status == SolveStatus::kSuccess; }
};

/// One series (method, restart) over the tolerance list.
struct WorkPrecisionSeries {
  ComputationMethod method = ComputationMethod::kArkodeErk54;
  bool restart = true;
  /// The largest worst_error / rtol over the series' successful runs [-] (0 if none).
  double worst_error_to_tolerance = 0.0;
  /// The rtol [-] where that largest ratio occurred (0 if no run succeeded).
  double at_tolerance = 0.0;
  int failures = 0;  ///< runs that did not succeed
  /// worst_error_to_tolerance <= kept_tolerance_ratio and no failures.
  bool kept_tolerance = true;
};

/// The cheapest successful run whose worst error reaches a target.
struct CheapestRun {
  double target_error = 0.0;  ///< the target worst error [-]
  /// Index into WorkPrecisionResult::points of the successful integration with the least
  /// seconds_per_impact and worst_error <= target_error (the first of equals); empty if no
  /// run reached it. The exact path is not a candidate.
  std::optional<std::size_t> point;
};

/// Termination of a study.
enum class WorkPrecisionStatus {
  kSuccess,          ///< every run succeeded
  kSomeRunsFailed,   ///< some integrations failed; they are points with their status
  kExactPathFailed,  ///< no reference: only the exact path's point is returned
};
std::string_view ToString(WorkPrecisionStatus status) noexcept;

/// The study: every point, the per-series check and the cheapest run per target.
struct WorkPrecisionResult {
  WorkPrecisionStatus status = WorkPrecisionStatus::kSuccess;
  std::string message;  ///< what happened, for people
  /// The exact path first, then per method, per restart series, per tolerance, in the
  /// options' order.
  std::vector<WorkPrecisionPoint> points;
  /// One per (method, restart), in the order of points.
  std::vector<WorkPrecisionSeries> series;
  /// One per WorkPrecisionOptions::error_targets, in that order.
  std::vector<CheapestRun> cheapest;
  double kept_tolerance_ratio = 100.0;  ///< the options' ratio the series were judged by [-]

  /// True unless the exact path failed (the errors then have a reference).
  bool IsUsable() const noexcept { return status != WorkPrecisionStatus::kExactPathFailed; }
  /// The point reaching `target_error` most cheaply among `cheapest`, or nullptr.
  const WorkPrecisionPoint* CheapestReaching(double target_error) const noexcept;
  /// One line: runs, failures, cheapest run for the tightest reached target, series that
  /// did not keep their tolerance.
  std::string BriefReport() const;
};

/// Measures the exact path and every (method, restart series, tolerance) of `options`.
/// @throws std::invalid_argument naming the scene field or the option, its value and the
/// allowed range.
WorkPrecisionResult MeasureWorkPrecision(const Scene& scene,
                                         const WorkPrecisionOptions& options = {});

/// The same for an already validated model.
/// @throws std::invalid_argument naming the option, its value and the allowed range.
WorkPrecisionResult MeasureWorkPrecision(const ImpactModel& model,
                                         const WorkPrecisionOptions& options = {});

}  // namespace covopt
