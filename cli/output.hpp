#pragma once
/// @file output.hpp
/// What `covopt simulate` prints and writes: the readable table, the JSON object, the
/// history CSV, and an atomic file writer. Physics comes from covopt::core only; this file
/// formats it.

#include <filesystem>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/core/time_integration.hpp"
#include "covopt/report/simulation_json.hpp"

namespace covopt::cli {

/// One finished computation with everything needed to report it (covopt::report's, whose
/// SimulationJson is the --json object).
using report::SimulationReport;

/// The scene in one short line, for titles: "10 kg at 2 m/s, R 15 mm; covering 15 mm,
/// 27.6 MPa; head 4.5 kg". The speed [m/s] goes with the body that moves: a fixed robot
/// reads "fixed robot, R 15 mm; ...; head 4.5 kg dropped onto it at 2.2 m/s", a fixed head
/// "...; head fixed, hit by the robot". Fields named in `omitted_fields` (dotted names:
/// robot.mass, robot.speed, robot.radius, covering.thickness, covering.modulus, head.mass)
/// are left out, e.g. the swept ones of a sweep chart; a body whose mass is omitted is
/// called neither fixed nor free.
std::string SceneHeadline(const Scene& scene, std::span<const std::string_view> omitted_fields = {});

/// The scene inputs SceneHeadline does not show that differ from the paper's scene
/// (Scene{}), skipping `omitted_fields`: {"scalp-thickness 4 mm", "literal thresholds"}.
std::vector<std::string> SceneDetailsBeyondHeadline(
    const Scene& scene, std::span<const std::string_view> omitted_fields = {});

/// The readable report: scene, peaks, verdicts, method and solver, warnings.
void PrintTable(std::ostream& out, const SimulationReport& report);

/// Every resolved scene input in SI; fixed masses are "fixed", a flat radius is "flat"
/// (report::SceneJson, parsed).
nlohmann::ordered_json SceneToJson(const Scene& scene);

/// A number for JSON, or null when it is not finite (JSON has no NaN or Infinity).
nlohmann::ordered_json JsonNumber(double value);

/// The integrator's counters as JSON: steps, rhs_evaluations, root_evaluations,
/// jacobian_evaluations, nonlinear_iterations, error_test_failures, convergence_failures,
/// restarts (report::SolverStatisticsJson, parsed).
nlohmann::ordered_json StatisticsToJson(const SolverStatistics& statistics);

/// The report as one JSON object, values in SI, keys carrying the unit
/// (max_penetration_m, peak_force_N, ...); missing or non-finite values are null.
/// scene.covering.material is the catalog material's name, or null. It is
/// report::SimulationJson parsed (the object Python's covopt.simulate returns).
nlohmann::ordered_json ToJson(const SimulationReport& report);

/// The CSV header of a history file.
inline constexpr std::string_view kHistoryCsvHeader =
    "time_s,penetration_m,penetration_rate_m_per_s,force_N,compressive_stress_Pa,"
    "tensile_stress_Pa,energy_density_J_per_m2";
/// The columns a scene with damping, braking or a neck (docs/model.md §10) adds after
/// kHistoryCsvHeader's: the bodies' speeds, the neck force and the work taken out
/// (HistorySample).
inline constexpr std::string_view kHistoryCsvExtendedColumns =
    ",robot_speed_m_per_s,head_speed_m_per_s,neck_force_N,dissipated_work_J";

/// The history as CSV text: kHistoryCsvHeader (and kHistoryCsvExtendedColumns for a scene
/// beyond the conservative two-mass model), then one row per sample (shortest
/// round-trip decimal numbers; a non-finite value is an empty field). tensile_stress_Pa is
/// σ_t = σ_c (1 - 2ν_t)/3 from the sample's compressive stress
/// (model.TensileFromCompressive), the stress the laceration limit judges.
std::string HistoryCsv(const ImpactModel& model, const std::vector<HistorySample>& history);

/// One CSV field: as it is, or, when it holds a comma, a quote or a line break, in double
/// quotes with inner quotes doubled (RFC 4180).
std::string CsvField(std::string_view text);

/// Writes `content` to `path` atomically: a temporary file in the same directory, flushed,
/// then renamed over `path`. A reader sees the old file or the whole new one.
/// @throws OutputError naming the file and the system's reason.
void WriteFileAtomically(const std::filesystem::path& path, std::string_view content);

}  // namespace covopt::cli
