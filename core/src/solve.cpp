// One impact on the path the scene and the options call for (covopt/core/solve.hpp): the rule
// Scene::has_energy_integral(), and the history's spacing from the contact duration.
#include "covopt/core/solve.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "exact_internal.hpp"
#include "numeric_format.hpp"

namespace covopt {
namespace {

/// The largest gap between history samples [s]: the contact duration over the samples asked
/// for, the duration exact for a conservative two-mass scene (a few µs), else that of a first
/// run without a history (0 when it failed: internal steps and events only).
double HistoryInterval(const ImpactModel& model, const SolveOptions& options) {
  if (!(options.history_samples_per_contact > 0.0)) return 0.0;
  double duration_s = 0.0;
  if (model.scene().is_conservative_two_mass()) {
    duration_s = ExactContactDuration(model, ExactPeaks(model));
  } else {
    TimeIntegrationOptions first_run = options.time_path;
    first_run.record_history = false;
    first_run.history_max_interval_s = 0.0;
    duration_s = SimulateImpact(model, first_run).contact_duration_s.value_or(0.0);
  }
  return duration_s / options.history_samples_per_contact;
}

}  // namespace

std::string_view ToString(PathChoice choice) noexcept {
  switch (choice) {
    case PathChoice::kAuto: return "auto";
    case PathChoice::kExact: return "exact";
    case PathChoice::kTimePath: return "time-path";
  }
  return "unknown";
}

PathChoice ChoosePath(const Scene& scene, const SolveOptions& options) {
  switch (options.path) {
    case PathChoice::kAuto:
      return scene.has_energy_integral() && !options.record_history ? PathChoice::kExact
                                                                    : PathChoice::kTimePath;
    case PathChoice::kExact:
      internal::CheckExactPathApplies(scene);
      if (options.record_history) {
        throw std::invalid_argument(
            "path exact computes no time history, which record_history needs; choose path auto "
            "or time-path");
      }
      return PathChoice::kExact;
    case PathChoice::kTimePath: return PathChoice::kTimePath;
  }
  throw std::invalid_argument("path must be auto, exact or time-path (got " +
                              std::to_string(static_cast<int>(options.path)) + ")");
}

ImpactResult Solve(const ImpactModel& model, const SolveOptions& options) {
  if (!(options.history_samples_per_contact >= 0.0 &&
        std::isfinite(options.history_samples_per_contact))) {
    throw std::invalid_argument("history_samples_per_contact must be a finite number >= 0 (got " +
                                internal::FormatNumber(options.history_samples_per_contact) + ")");
  }
  if (ChoosePath(model.scene(), options) == PathChoice::kExact) {
    return SolveExact(model, options.exact);
  }
  TimeIntegrationOptions time_path = options.time_path;
  time_path.record_history = options.record_history;
  time_path.history_max_interval_s = 0.0;  // set by Solve, never read from the options
  ValidateTimeIntegrationOptions(time_path, "time_path.");
  if (options.record_history) time_path.history_max_interval_s = HistoryInterval(model, options);
  return SimulateImpact(model, time_path);
}

ImpactResult Solve(const Scene& scene, const SolveOptions& options) {
  return Solve(ImpactModel::FromScene(scene), options);
}

}  // namespace covopt
