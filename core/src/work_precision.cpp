#include "covopt/core/work_precision.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <stdexcept>
#include <utility>

#include "covopt/core/exact.hpp"
#include "covopt/core/number_format.hpp"
#include "covopt/core/time_integration.hpp"
#include "numeric_format.hpp"

namespace covopt {
namespace {

using internal::FormatNumber;

/// CPU time of this thread [s]: what one impact costs, whatever else the machine does.
double ThreadCpuSeconds() {
  timespec now{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

/// Runs `compute` `repetitions` times, or automatically about `budget_s` worth (at least 3,
/// at most 301) judged by `first_seconds`, the time of a run just made (which also warmed
/// caches and workspaces), and returns the median time [s] and the count.
template <class Compute>
std::pair<double, int> MedianCpuTime(Compute&& compute, double first_seconds, int repetitions,
                                     double budget_s) {
  const int runs =
      repetitions > 0
          ? repetitions
          : std::clamp(static_cast<int>(std::ceil(budget_s / std::max(first_seconds, 1e-9))), 3,
                       301);
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(runs));
  for (int i = 0; i < runs; ++i) {
    const double start = ThreadCpuSeconds();
    compute();
    times.push_back(ThreadCpuSeconds() - start);
  }
  const auto middle = times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2);
  std::nth_element(times.begin(), middle, times.end());
  return {*middle, runs};
}

double RelativeError(double value, double reference) {
  return reference != 0.0 ? std::abs(value / reference - 1.0) : std::abs(value);
}

void SetErrors(WorkPrecisionPoint& point, const ImpactResult& result, const ImpactResult& exact) {
  const ImpactPeaks& p = result.peaks;
  const ImpactPeaks& q = exact.peaks;
  point.error_max_penetration = RelativeError(p.max_penetration_m, q.max_penetration_m);
  point.error_peak_force = RelativeError(p.peak_force_N, q.peak_force_N);
  point.error_max_compressive_stress =
      RelativeError(p.max_compressive_stress_Pa, q.max_compressive_stress_Pa);
  point.error_max_energy_density =
      RelativeError(p.max_energy_density_J_per_m2, q.max_energy_density_J_per_m2);
  point.error_contact_duration = RelativeError(result.contact_duration_s.value_or(0.0),
                                               exact.contact_duration_s.value_or(0.0));
  point.worst_error = std::max({point.error_max_penetration, point.error_peak_force,
                                point.error_max_compressive_stress, point.error_max_energy_density,
                                point.error_contact_duration});
}

void SetFailedErrors(WorkPrecisionPoint& point) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  point.error_max_penetration = kNaN;
  point.error_peak_force = kNaN;
  point.error_max_compressive_stress = kNaN;
  point.error_max_energy_density = kNaN;
  point.error_contact_duration = kNaN;
  point.worst_error = kNaN;
}

void Validate(const WorkPrecisionOptions& o) {
  if (o.methods.empty()) {
    throw std::invalid_argument("methods must name at least one time-integration method (got none)");
  }
  for (std::size_t i = 0; i < o.methods.size(); ++i) {
    const ComputationMethod method = o.methods[i];
    if (method == ComputationMethod::kExact || ToString(method) == "unknown") {
      throw std::invalid_argument("methods[" + std::to_string(i) +
                                  "] must be a time-integration method (got " +
                                  std::string(ToString(method)) + ")");
    }
    if (std::find(o.methods.begin(), o.methods.begin() + static_cast<std::ptrdiff_t>(i),
                  method) != o.methods.begin() + static_cast<std::ptrdiff_t>(i)) {
      throw std::invalid_argument("methods[" + std::to_string(i) +
                                  "] must not repeat a method (got " +
                                  std::string(ToString(method)) + " twice)");
    }
  }
  if (o.relative_tolerances.empty()) {
    throw std::invalid_argument("relative_tolerances must hold at least one tolerance (got none)");
  }
  for (std::size_t i = 0; i < o.relative_tolerances.size(); ++i) {
    const double rtol = o.relative_tolerances[i];
    if (!(rtol >= 1e-14 && rtol <= 1e-2)) {
      throw std::invalid_argument("relative_tolerances[" + std::to_string(i) +
                                  "] must be in [1e-14, 1e-2] (got " + FormatNumber(rtol) + ")");
    }
  }
  if (o.restart != RestartSeries::kOn && o.restart != RestartSeries::kOff &&
      o.restart != RestartSeries::kBoth) {
    throw std::invalid_argument("restart must be kOn, kOff or kBoth (got " +
                                std::to_string(static_cast<int>(o.restart)) + ")");
  }
  if (!(o.repetitions >= 0 && o.repetitions <= 100000)) {
    throw std::invalid_argument("repetitions must be in [0, 100000] (got " +
                                std::to_string(o.repetitions) + ")");
  }
  if (!(o.timing_budget_s > 0.0 && o.timing_budget_s <= 60.0)) {
    throw std::invalid_argument("timing_budget_s must be in (0, 60] s (got " +
                                FormatNumber(o.timing_budget_s) + ")");
  }
  if (o.max_steps_per_run < 10) {
    throw std::invalid_argument("max_steps_per_run must be >= 10 (got " +
                                std::to_string(o.max_steps_per_run) + ")");
  }
  for (std::size_t i = 0; i < o.error_targets.size(); ++i) {
    const double target = o.error_targets[i];
    if (!(target > 0.0 && std::isfinite(target))) {
      throw std::invalid_argument("error_targets[" + std::to_string(i) +
                                  "] must be a finite number > 0 (got " + FormatNumber(target) +
                                  ")");
    }
  }
  if (!(o.kept_tolerance_ratio > 0.0 && std::isfinite(o.kept_tolerance_ratio))) {
    throw std::invalid_argument("kept_tolerance_ratio must be a finite number > 0 (got " +
                                FormatNumber(o.kept_tolerance_ratio) + ")");
  }
}

std::vector<bool> RestartChoices(RestartSeries series) {
  switch (series) {
    case RestartSeries::kOn: return {true};
    case RestartSeries::kOff: return {false};
    case RestartSeries::kBoth: break;
  }
  return {true, false};
}

std::vector<WorkPrecisionSeries> Summarise(const std::vector<WorkPrecisionPoint>& points,
                                           double kept_ratio) {
  std::vector<WorkPrecisionSeries> series;
  for (const WorkPrecisionPoint& p : points) {
    if (p.method == ComputationMethod::kExact) continue;
    auto it = std::find_if(series.begin(), series.end(), [&](const WorkPrecisionSeries& s) {
      return s.method == p.method && s.restart == p.restart;
    });
    if (it == series.end()) {
      WorkPrecisionSeries added;
      added.method = p.method;
      added.restart = p.restart;
      series.push_back(added);
      it = series.end() - 1;
    }
    if (!p.ok()) {
      ++it->failures;
      continue;
    }
    const double ratio = p.worst_error / p.relative_tolerance;
    if (ratio > it->worst_error_to_tolerance) {
      it->worst_error_to_tolerance = ratio;
      it->at_tolerance = p.relative_tolerance;
    }
  }
  for (WorkPrecisionSeries& s : series) {
    s.kept_tolerance = s.failures == 0 && !(s.worst_error_to_tolerance > kept_ratio);
  }
  return series;
}

std::optional<std::size_t> Cheapest(const std::vector<WorkPrecisionPoint>& points, double target) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const WorkPrecisionPoint& p = points[i];
    if (p.method == ComputationMethod::kExact || !p.ok()) continue;
    if (!(p.worst_error <= target)) continue;
    if (!best || p.seconds_per_impact < points[*best].seconds_per_impact) best = i;
  }
  return best;
}

std::string SeriesLabel(ComputationMethod method, bool restart) {
  return std::string(ToString(method)) + (restart ? "" : ", no restart");
}

}  // namespace

std::string_view ToString(RestartSeries series) noexcept {
  switch (series) {
    case RestartSeries::kOn: return "on";
    case RestartSeries::kOff: return "off";
    case RestartSeries::kBoth: return "both";
  }
  return "unknown";
}

std::string_view ToString(WorkPrecisionStatus status) noexcept {
  switch (status) {
    case WorkPrecisionStatus::kSuccess: return "success";
    case WorkPrecisionStatus::kSomeRunsFailed: return "some_runs_failed";
    case WorkPrecisionStatus::kExactPathFailed: return "exact_path_failed";
  }
  return "unknown";
}

const WorkPrecisionPoint* WorkPrecisionResult::CheapestReaching(double target_error) const noexcept {
  for (const CheapestRun& run : cheapest) {
    if (run.target_error == target_error && run.point && *run.point < points.size()) {
      return &points[*run.point];
    }
  }
  return nullptr;
}

std::string WorkPrecisionResult::BriefReport() const {
  std::string report = "Work-precision " + std::string(ToString(status)) + ": ";
  if (!IsUsable()) return report + message;
  const std::size_t runs = points.empty() ? 0 : points.size() - 1;
  int failures = 0;
  std::size_t not_kept = 0;
  for (const WorkPrecisionSeries& s : series) {
    failures += s.failures;
    if (!s.kept_tolerance) ++not_kept;
  }
  report += std::to_string(runs) + " integrations in " + std::to_string(series.size()) +
            " series, " + std::to_string(failures) + " failed";
  // The tightest target some run reached.
  const CheapestRun* tightest = nullptr;
  for (const CheapestRun& run : cheapest) {
    if (run.point && (!tightest || run.target_error < tightest->target_error)) tightest = &run;
  }
  if (tightest) {
    const WorkPrecisionPoint& p = points[*tightest->point];
    report += "; cheapest to " + FormatScientific(tightest->target_error, 0) + ": " +
              SeriesLabel(p.method, p.restart) + " at rtol " +
              FormatScientific(p.relative_tolerance, 0) + ", " +
              FormatFixed(p.seconds_per_impact * 1e6, 1) + " µs per impact";
  }
  report += "; " + std::to_string(not_kept) + " series beyond " +
            FormatSignificant(kept_tolerance_ratio) + " x rtol or failing";
  return report;
}

WorkPrecisionResult MeasureWorkPrecision(const Scene& scene, const WorkPrecisionOptions& options) {
  Validate(options);
  return MeasureWorkPrecision(ImpactModel::FromScene(scene), options);
}

WorkPrecisionResult MeasureWorkPrecision(const ImpactModel& model,
                                         const WorkPrecisionOptions& options) {
  Validate(options);
  const std::vector<bool> restarts = RestartChoices(options.restart);
  WorkPrecisionProgress progress;
  progress.total_runs =
      1 + options.methods.size() * restarts.size() * options.relative_tolerances.size();
  const auto report_progress = [&] {
    ++progress.completed_runs;
    if (options.progress) options.progress(progress);
  };

  WorkPrecisionResult study;
  study.kept_tolerance_ratio = options.kept_tolerance_ratio;
  study.points.reserve(progress.total_runs);

  double start = ThreadCpuSeconds();
  const ImpactResult exact = SolveExact(model);
  const double exact_seconds = ThreadCpuSeconds() - start;
  {
    WorkPrecisionPoint reference;
    reference.status = exact.status;
    reference.message = exact.message;
    reference.warning_count = exact.warnings.size();
    const auto [seconds, runs] = MedianCpuTime([&] { (void)SolveExact(model); }, exact_seconds,
                                               options.repetitions, options.timing_budget_s);
    reference.seconds_per_impact = seconds;
    reference.timed_runs = runs;
    study.points.push_back(std::move(reference));
  }
  report_progress();
  if (!exact.ok()) {
    study.status = WorkPrecisionStatus::kExactPathFailed;
    study.message = "the exact path failed: " + exact.message;
    return study;
  }

  TimeIntegrator integrator;
  for (const ComputationMethod method : options.methods) {
    for (const bool restart : restarts) {
      for (const double tolerance : options.relative_tolerances) {
        TimeIntegrationOptions integration;
        integration.method = method;
        integration.relative_tolerance = tolerance;
        integration.restart_at_phase_switches = restart;
        integration.max_steps = options.max_steps_per_run;
        start = ThreadCpuSeconds();
        const ImpactResult result = integrator.Simulate(model, integration);
        const double first_seconds = ThreadCpuSeconds() - start;
        WorkPrecisionPoint point;
        point.method = method;
        point.restart = restart;
        point.relative_tolerance = tolerance;
        point.status = result.status;
        point.message = result.message;
        point.statistics = result.statistics;
        point.warning_count = result.warnings.size();
        point.energy_residual = result.energy_residual;
        if (result.ok()) {
          SetErrors(point, result, exact);
        } else {
          SetFailedErrors(point);
        }
        const auto [seconds, runs] =
            MedianCpuTime([&] { (void)integrator.Simulate(model, integration); }, first_seconds,
                          options.repetitions, options.timing_budget_s);
        point.seconds_per_impact = seconds;
        point.timed_runs = runs;
        study.points.push_back(std::move(point));
        report_progress();
      }
    }
  }

  study.series = Summarise(study.points, options.kept_tolerance_ratio);
  for (const double target : options.error_targets) {
    study.cheapest.push_back({target, Cheapest(study.points, target)});
  }
  int failures = 0;
  for (const WorkPrecisionSeries& s : study.series) failures += s.failures;
  study.status =
      failures == 0 ? WorkPrecisionStatus::kSuccess : WorkPrecisionStatus::kSomeRunsFailed;
  study.message = failures == 0
                      ? "every run succeeded"
                      : std::to_string(failures) + " of " +
                            std::to_string(study.points.size() - 1) +
                            " integrations failed; they are points with their status";
  return study;
}

}  // namespace covopt
