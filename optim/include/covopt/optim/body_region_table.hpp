#pragma once
/// @file body_region_table.hpp
/// One row of the all-regions speed-limit table (`covopt speed-limit --body-region`,
/// covopt.speed_limit(body_region=...)), whatever judged it: an ISO/TS 15066 region's
/// BodyRegionSpeedLimitRow or the head's pair of SpeedLimit. Made here, beside the limits it
/// reads; report/ writes it as JSON, CSV and text, and charts draw it.

#include <optional>
#include <string>

#include <covopt/core/result_summary.hpp>

#include "covopt/optim/body_region_check.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "covopt/optim/target_speed_limits.hpp"

namespace covopt::optim {

/// One row of the all-regions speed-limit table, whatever judged it (an ISO region's
/// BodyRegionSpeedLimitRow, or the head's pair of SpeedLimit).
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
  std::string bare_status;      ///< ToString(SpeedLimitStatus)
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
  /// Whose criteria: "ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M, transient (2×
  /// quasi-static), chest (sternum): 280 N, 240 N/cm²" or the head's ("skin injury, Park et al.
  /// 2011 ...").
  std::string criteria;
  /// The limit table of an ISO region's row (its title, edition, source, digest); none for the head.
  std::optional<LimitTableSummary> limit_table;
};

/// An ISO region's row at `robot_mass_kg`.
BodyRegionTableRow TableRow(double robot_mass_kg, const BodyRegionSpeedLimitRow& row);
/// The head's row at `robot_mass_kg`: Park et al.'s criteria, `criteria` naming them.
BodyRegionTableRow HeadTableRow(double robot_mass_kg, const SpeedLimit& bare,
                                const std::optional<SpeedLimit>& covered, std::string criteria);
/// A row of TargetSpeedLimitTable (the head's named by HeadCriteriaName), with
/// the covering's `material` ("" if none).
BodyRegionTableRow TableRow(const TargetSpeedLimit& row, const std::string& material);

}  // namespace covopt::optim
