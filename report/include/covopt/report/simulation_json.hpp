#pragma once
/// @file simulation_json.hpp
/// One simulation as JSON text: the object `covopt simulate --json` prints and
/// `covopt.simulate()` returns as a dict. Both call SimulationJson, so their keys and
/// values are the same by construction. Values are SI, keys carry the unit
/// (max_penetration_m, peak_force_N, ...); numbers are in shortest round-trip form, so a
/// parser gets back the exact doubles; a missing or non-finite value is null.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/impact_result.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/core/time_integration.hpp"
#include "covopt/core/verdict.hpp"

namespace covopt::report {

/// One finished computation with everything needed to report it.
struct SimulationReport {
  Scene scene;                   ///< the resolved scene (SI)
  ImpactResult result;           ///< from SolveExact or SimulateImpact
  /// The head's verdict (optim::SimulationVerdict: injury criteria, the covering's design
  /// rules, scope); the CLI and Python judge with the same call.
  Verdict verdict;
  /// The integrator's options when the time path ran; empty for the exact path.
  std::optional<TimeIntegrationOptions> time_options;
  /// The catalog material of the covering, if any.
  std::optional<std::string> covering_material;
  /// The material's ν is unknown in the catalog and the default was used.
  bool covering_poisson_assumed = false;
  /// What the caller noticed about its input (the CLI's and Python's input warnings),
  /// reported after the result's own warnings, without a code.
  std::vector<std::string> input_warnings;
  /// Verdict::safe(): every counted injury criterion and design rule holds.
  bool safe() const noexcept { return verdict.safe(); }
};

/// The report as one JSON object: the peaks (max_penetration_m, peak_force_N,
/// contact_duration_s, ...), the laceration and contusion verdicts (value, limit, ratio,
/// safe, derated_limit and safety_factor), the fracture one (the same in N, with the struck area,
/// the published range and the source), the crush one (or null), safe (Verdict::safe()),
/// verdict (VerdictJson's object), scope, method, solver (status, message, raw code,
/// statistics; tolerances and energy_residual on the time path), scene (SceneJson, with
/// covering.material the catalog name or null), warnings and warning_codes.
/// `indent` as in nlohmann's dump: 2 (the CLI's), or -1 for one line.
std::string SimulationJson(const SimulationReport& report, int indent = 2);

/// Every scene input in SI as a JSON object {robot, covering, head, scalp, skull, model};
/// an infinite mass is "fixed", an infinite robot radius "flat".
std::string SceneJson(const Scene& scene, int indent = 2);

/// Where a scene input is in a result's JSON: the dotted JSON path of a Scene field
/// (covopt/core/scene_fields.hpp, by its dotted name "robot.mass": "scene.robot.mass_kg"), of
/// the scene's choices ("covering.law", "head.area", "model.thresholds") and of the covering's
/// catalog material ("covering.material": "scene.covering.material"), as SceneJson and
/// SimulationJson write them; nullopt for any other name.
std::optional<std::string> SceneJsonPath(std::string_view dotted_name);

/// The integrator's counters as a JSON object: steps, rhs_evaluations, root_evaluations,
/// jacobian_evaluations, nonlinear_iterations, error_test_failures, convergence_failures,
/// restarts.
std::string SolverStatisticsJson(const SolverStatistics& statistics, int indent = 2);

}  // namespace covopt::report
