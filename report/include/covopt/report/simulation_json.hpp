#pragma once
/// @file simulation_json.hpp
/// One simulation as JSON text: the object `covopt simulate --json` prints and
/// `covopt.simulate()` returns as a dict. Both call SimulationJson, so their keys and
/// values are the same by construction. Values are SI, keys carry the unit
/// (max_penetration_m, peak_force_N, ...); numbers are in shortest round-trip form, so a
/// parser gets back the exact doubles; a missing or non-finite value is null.

#include <optional>
#include <string>
#include <vector>

#include "covopt/core/impact_result.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/core/time_integration.hpp"

namespace covopt::report {

/// One finished computation with everything needed to report it.
struct SimulationReport {
  Scene scene;                   ///< the resolved scene (SI)
  ImpactResult result;           ///< from SolveExact or SimulateImpact
  /// The verdicts: JudgeInjuries(result.peaks, limits, safety_factor, scene.head.area).
  InjuryAssessment assessment;
  /// The integrator's options when the time path ran; empty for the exact path.
  std::optional<TimeIntegrationOptions> time_options;
  /// The catalog material of the covering, if any.
  std::optional<std::string> covering_material;
  /// The material's ν is unknown in the catalog and the default was used.
  bool covering_poisson_assumed = false;
  /// The verdicts are safe when safety_factor x ratio <= 1, i.e. within the derated limits
  /// limit / safety_factor [-]; 1 = the limits themselves.
  double safety_factor = 1.0;
  /// The crush verdict (docs/model.md §12) when the covering is a catalog material of known
  /// compressive strength: σ_c,max [Pa] against the strength [Pa] (optim::CrushVerdict); part
  /// of the overall verdict. Empty otherwise.
  std::optional<InjuryVerdict> crush;
  /// What the verdict covers, one sentence each (optim::HeadVerdictScope).
  std::vector<std::string> scope;
  /// What the caller noticed about its input (the CLI's and Python's input warnings),
  /// reported after the result's own warnings, without a code.
  std::vector<std::string> input_warnings;
  /// The laceration, contusion and (when checked) crush verdicts are all safe.
  bool safe() const noexcept { return assessment.safe() && (!crush || crush->safe); }
};

/// Judges peaks against limits with a safety factor [-] (>= 1): each ratio stays
/// value / limit, and a verdict is safe when safety_factor x ratio <= 1 (the value is
/// within the derated limit limit / safety_factor).
/// The fracture verdict judges F_max against the lowest published fracture force of `area`
/// (Assess).
InjuryAssessment JudgeInjuries(const ImpactPeaks& peaks, const InjuryLimits& limits, double safety_factor,
                               HeadArea area = HeadArea::kFrontal) noexcept;

/// The report as one JSON object: the peaks (max_penetration_m, peak_force_N,
/// contact_duration_s, ...), the laceration and contusion verdicts (value, limit, ratio,
/// safe, derated_limit and safety_factor), the fracture verdict (the same, in N, with the
/// struck area, the published range and the source), safe, method, solver (status, message, raw code,
/// statistics; tolerances and energy_residual on the time path), scene (SceneJson, with
/// covering.material the catalog name or null), warnings and warning_codes.
/// `indent` as in nlohmann's dump: 2 (the CLI's), or -1 for one line.
std::string SimulationJson(const SimulationReport& report, int indent = 2);

/// Every scene input in SI as a JSON object {robot, covering, head, scalp, skull, model};
/// an infinite mass is "fixed", an infinite robot radius "flat".
std::string SceneJson(const Scene& scene, int indent = 2);

/// The integrator's counters as a JSON object: steps, rhs_evaluations, root_evaluations,
/// jacobian_evaluations, nonlinear_iterations, error_test_failures, convergence_failures,
/// restarts.
std::string SolverStatisticsJson(const SolverStatistics& statistics, int indent = 2);

}  // namespace covopt::report
