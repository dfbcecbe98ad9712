#pragma once
/// @file body_contact_json.hpp
/// ISO/TS 15066 body-region results as JSON text and CSV cells (docs/model.md §13): the
/// verdicts of `covopt simulate --body-region`, the all-regions speed-limit table of
/// `covopt speed-limit --body-region`, and the design of `covopt optimize --body-region`. SI
/// values, units in the keys; a value not evaluated (the bare robot's pressure without a contact
/// area) or not existing (no safe speed) is null; an infinite mass is "fixed", a flat robot
/// "flat". Every verdict carries "criteria" (whose) and "scope" (its limits in words).

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/body_contact.hpp"
#include "covopt/optim/body_region_check.hpp"
#include "covopt/optim/body_region_trajectory.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "covopt/optim/target_speed_limits.hpp"
#include "covopt/report/history_csv.hpp"

namespace covopt::report {

/// The robot and covering of a body contact: {robot_mass_kg, speed_m_per_s, robot_radius_m,
/// covering {youngs_modulus_Pa, poisson_ratio, thickness_m, material}, contact,
/// contact_area_m2} (without_robot: the mass and speed left out, as for a table over them).
std::string BodyContactSceneJson(const BodyContactScene& scene, const std::optional<std::string>& material,
                                 bool without_robot = false);

/// One verdict: {region, area, area_title, contact, criteria, scope, method, reduced_mass_kg,
/// energy_transferred_J, peak_force_N, peak_pressure_Pa, contact_radius_m,
/// covering_deflection_m, body_deflection_m, compression_ratio, fully_compressed,
/// force {value_N, limit_N, ratio}, pressure {value_Pa, limit_Pa, ratio, evaluated},
/// crush {check, ratio}, governing, governing_ratio, safety_factor, admissible, margin}.
std::string BodyRegionJudgementJson(const optim::BodyRegionJudgement& judgement, double safety_factor);

/// The time path's warnings of one region's contact (BodyContactResult::warnings: the integrator
/// did not keep its tolerance), of its judgement (a braking robot's is the time path's) and of
/// `time_path` (a time-path run beside the exact verdict) when given, each "<region> (<area>):
/// <message>": the lines simulate --body-region adds to its warnings.
std::vector<std::string> TimePathWarnings(const optim::BodyRegionJudgement& judgement,
                                          const BodyContactResult* time_path);

/// The contact of a time-path run (simulate with a time path beside the exact verdict):
/// {method, peak_force_N, peak_pressure_Pa, contact_radius_m, covering_deflection_m,
/// body_deflection_m, max_approach_m, compression_ratio, fully_compressed,
/// energy_transferred_J, contact_duration_s, rebound_speed_m_per_s, energy_residual, warnings};
/// a value not evaluated is null.
std::string BodyContactTimePathJson(const BodyContactResult& time_path);

/// The time history of a body contact as columns: time_s, approach_m, approach_rate_m_per_s,
/// force_N, robot_speed_m_per_s, braking_work_J.
std::vector<HistoryColumn> BodyContactHistoryColumns(std::span<const BodyContactSample> history);

/// `simulate --body-region`: {scene (BodyContactSceneJson), safety_factor, regions
/// [BodyRegionJudgementJson...], head (the head's simulation object, `head_json`, or null),
/// safe (every verdict), summary (every region's rows, then the head's), warnings}.
std::string BodyContactSimulationJson(const BodyContactScene& scene, const std::optional<std::string>& material,
                                      std::span<const optim::BodyRegionJudgement> regions, double safety_factor,
                                      const std::optional<std::string>& head_json,
                                      std::span<const std::string> warnings);

/// One row of the all-regions speed-limit table, whatever judged it (an ISO region's
/// optim::BodyRegionSpeedLimitRow, or the head's pair of optim::SpeedLimit).
struct BodyRegionTableRow {
  std::string material;        ///< the covering's catalog material; "" if none
  double robot_mass_kg = 0.0;  ///< [kg]; +inf: fixed
  std::string region;          ///< "chest", or "head"
  std::string area;            ///< "sternum"; "" for the head
  std::string contact;         ///< "transient" or "clamped"
  std::optional<double> force_limit_N;      ///< F_lim [N]; empty for the head
  std::optional<double> pressure_limit_Pa;  ///< p_lim [Pa]; empty for the head
  /// The max safe speed [m/s]; empty when no speed is safe. `bare_*` without the covering.
  std::optional<double> bare_max_speed_m_per_s;
  std::string bare_limited_by;  ///< "force", "pressure", ...; "laceration", ... for the head
  std::string bare_status;      ///< optim::ToString(SpeedLimitStatus)
  bool has_covering = false;
  std::optional<double> covered_max_speed_m_per_s;
  std::string covered_limited_by;  ///< "" without a covering
  std::string covered_status;      ///< "" without a covering
  std::optional<double> gain;      ///< covered / bare [-]
  /// The covering's law ("foam", "hertz"; "" without a covering), its validity at the covered
  /// limit, and the speed [m/s] at which it is used up (empty bare, above 100 m/s, or braked).
  std::string covering_law;
  bool within_law = true;
  std::string validity_note;
  std::optional<double> covering_used_up_m_per_s;
  /// Whose criteria: "ISO/TS 15066:2016 transient, chest (sternum): 280 N, 240 N/cm²" or the
  /// head's ("skin injury, Park et al. 2011 ...").
  std::string criteria;
};

/// An ISO region's row at `robot_mass_kg`.
BodyRegionTableRow TableRow(double robot_mass_kg, const optim::BodyRegionSpeedLimitRow& row);
/// The head's row at `robot_mass_kg`: Park et al.'s criteria, `criteria` naming them.
BodyRegionTableRow HeadTableRow(double robot_mass_kg, const optim::SpeedLimit& bare,
                                const std::optional<optim::SpeedLimit>& covered, std::string criteria);
/// A row of optim::TargetSpeedLimitTable (the head's named by optim::HeadCriteriaName), with
/// the covering's `material` ("" if none).
BodyRegionTableRow TableRow(const optim::TargetSpeedLimit& row, const std::string& material);

/// The columns, as the JSON rows' keys and the CSV header: material, robot_mass_kg, region, area,
/// contact, force_limit_N, pressure_limit_Pa, bare_max_speed_m_per_s, bare_limited_by,
/// covered_max_speed_m_per_s, covered_limited_by, gain, criteria.
std::span<const std::string_view> BodyRegionTableColumns() noexcept;
/// One row's cells (shortest round-trip numbers, "fixed", "" for null).
std::vector<std::string> BodyRegionTableCsvCells(const BodyRegionTableRow& row);

/// `speed-limit --body-region`: {solve_for "speed", summary (one limit row per row), scene (without the robot's mass and speed), criterion (in words),
/// safety_factor, rows [BodyRegionTableColumns keys, plus bare_status, covered_status],
/// warnings}.
std::string BodyRegionSpeedLimitJson(const BodyContactScene& scene, const std::optional<std::string>& material,
                                     std::string_view criterion, double safety_factor,
                                     std::span<const BodyRegionTableRow> rows,
                                     std::span<const std::string> warnings);

/// `optimize --body-region --speed V`: {message, summary, speed_m_per_s, recommendation (the
/// candidate, or null), bare_robot {safe, regions [...], head}, candidates [{material,
/// youngs_modulus_Pa, thickness_m (null: none in range), admissible, governing_ratio,
/// governing_where, regions [...], head}], scope, warnings}. A head score is {laceration_ratio,
/// contusion_ratio, compression_ratio, criteria}.
std::string BodyRegionDesignJson(const optim::BodyRegionDesignRequest& request,
                                 const optim::BodyRegionDesignResult& result, std::string_view criterion,
                                 std::span<const std::string> warnings);

/// `robot --trajectory --body-region`: {status, message, summary (the regions'), safe_speed_scale (null at rest),
/// worst_sample (index or null), unsafe_sample_count, criterion, scene (without the robot's mass
/// and speed), regions [{region, area, contact, scope}], head ({status, safe_speed_scale,
/// message} of the head's own check, or null), samples [{time_s, speed_m_per_s,
/// reflected_mass_kg, moving, worst_ratio, binding, worst_region, safe,
/// max_safe_speed_m_per_s, limiting_region, limited_by, speed_scale}], warnings}.
struct HeadTrajectorySummary {
  std::string status;
  double safe_speed_scale = 0.0;
  std::string message;
};
/// `safety_factor`: the rule's (the samples' ratios are unscaled).
std::string BodyRegionTrajectoryJson(const optim::BodyRegionTrajectoryCheck& check,
                                     std::span<const materials::BodyLimits> regions, const BodyContactScene& scene,
                                     const std::optional<HeadTrajectorySummary>& head, std::string_view criterion,
                                     double safety_factor, std::span<const std::string> warnings);

}  // namespace covopt::report
