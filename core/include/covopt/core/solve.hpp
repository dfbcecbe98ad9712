#pragma once
/// @file solve.hpp
/// One impact, whichever path answers it: the one call behind `covopt simulate`, Python's
/// covopt.simulate() and the sweep's points.
///
/// Solve chooses between the exact path (exact.hpp: energy balance and quadrature, conservative
/// or with contact damping) and the time path (time_integration.hpp: SUNDIALS with events) by
/// one rule, Scene::has_energy_integral(): a scene with an energy integral takes the exact path
/// unless a history is asked for; a braking robot or a neck has only the time path
/// (docs/model.md §3, §10). A history is sampled at least SolveOptions::history_samples_per_contact
/// times over the contact by the integrator's dense output, so charts are smooth at the default
/// tolerance.
///
///     covopt::SolveOptions options;            // automatic choice, exact path where it answers
///     options.record_history = true;           // the time path, ~400 samples over the contact
///     const covopt::ImpactResult result = covopt::Solve(scene, options);

#include "covopt/core/exact.hpp"
#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/core/time_integration.hpp"

namespace covopt {

/// Which path answers an impact.
enum class PathChoice {
  /// The exact path where the scene has an energy integral (Scene::has_energy_integral()) and
  /// no history is asked for; the time path otherwise.
  kAuto,
  /// The exact path; refused for a scene without an energy integral or with a history.
  kExact,
  /// The time path, whatever the scene.
  kTimePath,
};

/// "auto", "exact" or "time-path".
std::string_view ToString(PathChoice choice) noexcept;

/// Options of Solve.
struct SolveOptions {
  /// Which path answers. Default: kAuto (the exact path where it answers every quantity).
  PathChoice path = PathChoice::kAuto;
  /// Options of the exact path. Default: peaks and contact duration.
  ExactOptions exact;
  /// Options of the time path: integrator, tolerances, step limit. Default: ARKODE's
  /// Dormand-Prince 5(4) at rtol 1e-8 (TimeIntegrationOptions). Its record_history and
  /// history_max_interval_s are not read: Solve sets them from the two fields below.
  TimeIntegrationOptions time_path;
  /// Record the force/time history into ImpactResult::history. Needs the time path: kAuto
  /// takes it, kExact is refused. Default: false.
  bool record_history = false;
  /// With record_history: at least this many samples over the contact [-], finite, >= 0. The
  /// integrator's dense output fills every gap wider than T / this, T the contact duration
  /// (the exact one for a conservative two-mass scene, else that of a first run without a
  /// history). 0: the internal steps and events only. Default: 400 (smooth charts).
  double history_samples_per_contact = 400.0;
};

/// The path Solve takes for `scene` with `options`: PathChoice::kExact or kTimePath (never
/// kAuto). Needs no validated scene.
/// @throws std::invalid_argument for PathChoice::kExact on a scene without an energy integral
///         or with record_history, naming the option.
PathChoice ChoosePath(const Scene& scene, const SolveOptions& options);

/// Solves one impact on the path ChoosePath names. Numerical failures of the time path come
/// back as ImpactResult::status; ImpactResult::method says which path (and integrator) answered.
/// @throws std::invalid_argument for an option out of range or a refused path (naming it).
ImpactResult Solve(const ImpactModel& model, const SolveOptions& options = {});

/// Validates `scene` (ImpactModel::FromScene) and solves it.
/// @throws std::invalid_argument for a scene field or an option out of range (naming it).
ImpactResult Solve(const Scene& scene, const SolveOptions& options = {});

}  // namespace covopt
